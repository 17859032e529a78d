// What the exhibit page's browser test and benchmark share (browser_test.js,
// browser_bench.js): a static server on localhost, Debian's chromium under puppeteer-core, a
// watch for console errors, and the run as the page shows it and as the native CLI reports it.
'use strict';

const childProcess = require('child_process');
const fs = require('fs');
const http = require('http');
const os = require('os');
const path = require('path');
const zlib = require('zlib');
const puppeteer = require('puppeteer-core');

const TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.wasm': 'application/wasm',
  '.png': 'image/png',
  '.svg': 'image/svg+xml',
  '.md': 'text/plain; charset=utf-8',
};

const COMPRESSED = new Set(['.html', '.js', '.css', '.wasm', '.svg']);

// Serves the files of `root` on 127.0.0.1 (`port`, or a free one); resolves to { url, close }.
function startServer(root, port = 0) {
  const gzipped = new Map(); // file -> { mtime, bytes }
  const gzipOf = (file) => {
    const mtime = fs.statSync(file).mtimeMs;
    let hit = gzipped.get(file);
    if (!hit || hit.mtime !== mtime) {
      hit = { mtime, bytes: zlib.gzipSync(fs.readFileSync(file), { level: 9 }) };
      gzipped.set(file, hit);
    }
    return hit;
  };
  // The site's own files compressed before the first visitor, so no page waits for it.
  for (const name of fs.readdirSync(root)) {
    const file = path.join(path.resolve(root), name);
    if (COMPRESSED.has(path.extname(name)) && fs.statSync(file).isFile()) gzipOf(file);
  }
  const server = http.createServer((req, res) => {
    const name = decodeURIComponent(new URL(req.url, 'http://localhost').pathname);
    const file = path.resolve(root, '.' + path.normalize(name === '/' ? '/index.html' : name));
    if (!file.startsWith(path.resolve(root) + path.sep) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
      res.writeHead(404);
      res.end('not found');
      return;
    }
    const type = TYPES[path.extname(file)] || 'application/octet-stream';
    // The module and the scripts compressed when the browser takes gzip (every browser does):
    // parsons_web.wasm goes from MiB to a third of it (docs/web.md says how any server should
    // do this). `Vary` tells caches the answer depends on Accept-Encoding.
    if (COMPRESSED.has(path.extname(file)) && /\bgzip\b/.test(req.headers['accept-encoding'] || '')) {
      // Compressed once a file (and again when it changes), not at every request.
      const hit = gzipOf(file);
      res.writeHead(200, { 'Content-Type': type, 'Content-Encoding': 'gzip', Vary: 'Accept-Encoding',
                           'Content-Length': hit.bytes.length });
      res.end(hit.bytes);
      return;
    }
    res.writeHead(200, { 'Content-Type': type, Vary: 'Accept-Encoding' });
    fs.createReadStream(file).pipe(res);
  });
  return new Promise((resolve) => {
    server.listen(port, '127.0.0.1', () => {
      resolve({ url: `http://127.0.0.1:${server.address().port}`, close: () => server.close() });
    });
  });
}

// Debian's chromium (package chromium), headless, with a fresh profile; no network beyond
// localhost is asked for.
function launchChromium(profileDir) {
  const executablePath = process.env.PARSONS_CHROMIUM || '/usr/bin/chromium';
  if (!fs.existsSync(executablePath)) {
    throw new Error(`${executablePath} not found: run scripts/install-deps.sh (Debian's chromium)`);
  }
  fs.mkdirSync(profileDir, { recursive: true });
  const args = ['--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
                '--disable-component-update', '--disable-sync', '--disable-dev-shm-usage'];
  if (typeof process.getuid === 'function' && process.getuid() === 0) args.push('--no-sandbox');
  return puppeteer.launch({ executablePath, headless: true, userDataDir: profileDir, args });
}

// Every console error, uncaught page error and failed request goes into `problems`.
function watchPage(page, problems) {
  page.on('console', (m) => { if (m.type() === 'error') problems.push(`console: ${m.text()}`); });
  page.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  page.on('requestfailed', (r) => {
    // A download the test asked for ends its request as aborted; that is no failure.
    if (!(r.failure() && /ERR_ABORTED/.test(r.failure().errorText) && r.url().startsWith('blob:'))) {
      problems.push(`request failed: ${r.url()} ${r.failure() ? r.failure().errorText : ''}`);
    }
  });
}

// The native CLI's report of a run of `deck`.
function nativeReport(exe, deck, workDir, name) {
  const file = path.join(workDir, `${name}.report.json`);
  const r = childProcess.spawnSync(exe, ['run', deck, '-q', '--report', file], { encoding: 'utf8' });
  if (r.status !== 0 && r.status !== 3) throw new Error(`parsons run ${deck}: ${r.stderr}`);
  return JSON.parse(fs.readFileSync(file, 'utf8'));
}

// The run as the page shows it: machine time, stop reason, each axis's counters and position.
function pageResult(page) {
  return page.evaluate(() => {
    const axes = {};
    for (const tr of document.querySelectorAll('#positions tr[data-axis]')) {
      axes[tr.dataset.axis] = { counters: tr.querySelector('.counters').textContent, real: tr.querySelector('.real').textContent };
    }
    const state = document.getElementById('run-state');
    return { seconds: Number(document.getElementById('machine-time').dataset.seconds), reason: state.dataset.reason, axes };
  });
}

// WORK_DIR/NAME: the deck `sample` punched by the native CLI, with a card-start mark put inside
// card 2 at column 11, so that reading it fails there. Its path.
function badCbn(exe, sample, workDir, name) {
  const good = path.join(workDir, `${name}.good.cbn`);
  childProcess.spawnSync(exe, ['punch', sample, '-o', good]);
  const bytes = fs.readFileSync(good);
  bytes[181] = 0xbf; // card 2, column 11: a card-start mark inside the card
  const bad = path.join(workDir, name);
  fs.writeFileSync(bad, bytes);
  return bad;
}

module.exports = { startServer, launchChromium, watchPage, nativeReport, pageResult, badCbn, tmp: os.tmpdir };
