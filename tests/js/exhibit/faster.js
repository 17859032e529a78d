// Issue 31, item 7 ("faster") and the --html part of item 4, run by tests/js/browser_test.js:
//   - the server answers gzip for the module and the scripts, and the page loads so;
//   - the first view ready (window.parsonsReadyAt) under 400 ms, and the demo deck's first
//     press "to the end" against the native `parsons run`: both printed;
//   - `parsons run DECK --html` of the demo deck, the deck typed with its absolute path: under
//     1 MB, the file name only (no folder of the path anywhere in the file), the packed record
//     unpacked (time printed) bit for bit the record the live page runs, ending on the native
//     report.
'use strict';

const childProcess = require('child_process');
const fs = require('fs');
const http = require('http');
const path = require('path');
const zlib = require('zlib');
const { watchPage, nativeReport, pageResult } = require('../web_support');

// One GET of `url`: status, headers and the body as sent (not decompressed).
function get(url, headers) {
  return new Promise((resolve, reject) => {
    http.get(url, { headers }, (res) => {
      const parts = [];
      res.on('data', (d) => parts.push(d));
      res.on('end', () => resolve({ status: res.statusCode, headers: res.headers, body: Buffer.concat(parts) }));
    }).on('error', reject);
  });
}

// A digest of the viewer's four arrays, their bytes as they are (so -0, NaN and the last bit
// of every number count).
function recordDigest(page) {
  return page.evaluate(async () => {
    const a = window.parsonsViewer.a;
    const out = {};
    for (const k of ['change_t', 'change_id', 'change_v', 'motion']) {
      const d = await crypto.subtle.digest('SHA-256', new Uint8Array(a[k].buffer, a[k].byteOffset, a[k].byteLength));
      out[k] = `${a[k].length}:${[...new Uint8Array(d)].map((b) => b.toString(16).padStart(2, '0')).join('')}`;
    }
    return out;
  });
}

// The native process's time, median of 5, less starting /bin/true.
function nativeMs(exe, args) {
  const once = (e, a) => {
    const t0 = process.hrtime.bigint();
    const r = childProcess.spawnSync(e, a, { encoding: 'utf8' });
    if (r.status !== 0 && r.status !== 3) throw new Error(`${e} ${a.join(' ')}: ${r.stderr}`);
    return Number(process.hrtime.bigint() - t0) / 1e6;
  };
  const median = (f) => { const xs = [1, 2, 3, 4, 5].map(f).sort((x, y) => x - y); return xs[2]; };
  return median(() => once(exe, args)) - median(() => once('/bin/true', []));
}

module.exports = async function faster(t) {
  const { server, site, workDir, parsonsExe, problems, check, parsons, compareRun, browser } = t;

  // ---- compressed on the wire
  const wasmFile = fs.readFileSync(path.join(site, 'parsons_web.wasm'));
  for (const name of ['parsons_web.wasm', 'parsons_web.js', 'viewer.js', 'index.html']) {
    const r = await get(`${server.url}/${name}`, { 'Accept-Encoding': 'gzip, deflate, br' });
    const plain = fs.readFileSync(path.join(site, name));
    const same = r.headers['content-encoding'] === 'gzip' && zlib.gunzipSync(r.body).equals(plain);
    check(r.status === 200 && same && /Accept-Encoding/i.test(r.headers.vary || ''),
          `the server sends ${name} gzipped (Content-Encoding, Vary), the same bytes once unpacked`,
          `${plain.length} bytes, ${r.body.length} on the wire, ${r.headers['content-encoding']}`);
  }
  const raw = await get(`${server.url}/parsons_web.wasm`, {});
  check(raw.headers['content-encoding'] === undefined && raw.body.equals(wasmFile) &&
        raw.headers['content-type'] === 'application/wasm',
        'without Accept-Encoding the module is sent as it is, as application/wasm');

  // ---- the first view, and the first press on the demo deck
  const page = await t.open('laptop');
  const wire = await page.evaluate(() => performance.getEntriesByType('resource')
    .filter((e) => e.name.endsWith('.wasm')).map((e) => [e.transferSize, e.decodedBodySize])[0]);
  check(wire && wire[0] < wire[1] * 0.6, 'the page got the module compressed',
        wire ? `${wire[0]} bytes on the wire for ${wire[1]}` : 'no .wasm request');
  const [readyMs, settledMs] = await page.evaluate(() => [window.parsonsReadyAt, window.parsonsSettledAt]);
  console.log(`first view ready ${readyMs.toFixed(0)} ms after navigation (issue: under 400 ms; ` +
              `${readyMs < 400 ? 'met' : 'NOT met'} here); the cabinet standing at card 1 at ${settledMs.toFixed(0)} ms`);
  // Printed against the 400 ms (met with nothing else running: the sample deck now runs
  // after the page is ready); asserted loosely, as a shared CI machine's load can double it.
  check(readyMs > 0 && readyMs < 2500, 'the first view is ready within 2.5 s', `${readyMs.toFixed(0)} ms`);
  // A deck loaded while the viewer plays is not run behind the visitor's back: the record they
  // watch plays on, and their next press runs the new deck.
  await page.click('.speeds [data-speed="100"]');
  await page.click('#play');
  await page.$eval('#load-demo', (b) => b.click());
  await page.waitForFunction(() => document.querySelectorAll('#cards figure').length > 50);
  await new Promise((r) => setTimeout(r, 300));
  const playing = await page.evaluate(() => ({
    state: document.getElementById('run-state').textContent,
    ran: document.getElementById('run-state').dataset.ran,
    finish: Number(document.getElementById('scrub').max),
  }));
  await page.click('#pause');
  check(playing.state === 'running' && playing.ran === 'false',
        'a deck loaded while the viewer plays leaves the playing record alone until the next press',
        JSON.stringify(playing));
  await page.click('.speeds [data-speed="1"]');
  // The button is in the deck's drawer, closed on the first view: pressed as a script would.
  // The page runs the deck once it is punched, in a task of its own: the cabinet then stands at
  // its first card, and the press finds it run.
  await page.$eval('#load-demo', (b) => b.click());
  await page.waitForFunction(() => document.querySelectorAll('#cards figure').length > 50);
  await page.waitForSelector('#run-state[data-ran="true"]');
  const before = await page.evaluate(() => ({
    ...window.parsonsTiming,
    t: Number(document.getElementById('machine-time').dataset.seconds),
    finish: Number(document.getElementById('scrub').max),
    state: document.getElementById('run-state').textContent,
  }));
  // The finished view is whole when the press's time is taken: the picture holds the whole path
  // and the positions are written.
  await page.$eval('#to-end', (b) => b.addEventListener('click', () => {
    const v = window.parsonsViewer;
    const timed = v.onFinished;
    let strokes = 0;
    const strokePath = v.strokePath;
    v.strokePath = function (...a) { strokes++; return strokePath.apply(this, a); };
    v.onFinished = () => {
      delete v.strokePath;
      window.finishedSeen = { drawn: v.drawnMotion, records: v.a.motion.length / 8, whole: !!v.wholePath, strokes,
                              real: document.querySelector('#positions tr[data-axis] .real').textContent };
      timed();
    };
  }, { capture: true, once: true }));
  await page.click('#to-end');
  await page.waitForSelector('#run-state[data-finished="true"]');
  const timing = await page.evaluate(() => window.parsonsTiming);
  const seen = await page.evaluate(() => window.finishedSeen);
  const ended = await page.$eval('#machine-time', (e) => Number(e.dataset.seconds));
  check(before.runOnPress === false && before.t === 0 && before.state === 'ready' && before.finish === ended,
        'the demo deck is run once punched, before any press: the cabinet stands at its start, ready, ' +
        'with the record the press then shows', JSON.stringify({ ...before, ended }));
  check(timing.runOnPress === false && seen && seen.drawn === seen.records && seen.real !== '',
        'the press finds the deck run, and its time is taken with the picture and positions drawn',
        JSON.stringify({ runOnPress: timing.runOnPress, seen }));
  const demoDir = path.join(workDir, 'faster-demo');
  const d = parsons(['demo', '--out', demoDir]);
  check(d.status === 0, 'parsons demo runs', d.stderr);
  const deck = path.join(demoDir, 'airfoil-template', 'naca2412.cbn'); // absolute
  const native = nativeMs(parsonsExe, ['run', deck, '-q', '--report', path.join(workDir, 'faster.json')]);
  console.log(`demo deck, first press "to the end": ${timing.toEndMs.toFixed(1)} ms; ` +
              `native parsons run ${native.toFixed(1)} ms: ${(timing.toEndMs / native).toFixed(2)}x (issue: within 2x); ` +
              `the run once punched, before the press: ${(before.runMs + before.loadMs).toFixed(0)} ms ` +
              `(the WebAssembly run ${before.runMs.toFixed(0)} ms, the view loaded ${before.loadMs.toFixed(0)} ms)`);
  check(timing.toEndMs > 0, 'the page times its first press');
  const live = await recordDigest(page);
  // The jump drew the picture from the whole path drawn once after the load; it is the picture
  // playing draws, stroke by stroke (three here): the pixels that differ by more than a shade
  // (the edges where two strokes meet) are counted.
  const picture = await page.evaluate(() => {
    const v = window.parsonsViewer;
    const c = document.getElementById('from-above');
    const grab = () => c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const jumped = grab();
    for (const f of [0.37, 0.8, 1]) v.seek(v.finish * f);
    const played = grab();
    let differ = 0;
    for (let i = 0; i < jumped.length; i += 4) {
      let d = 0;
      for (let j = 0; j < 3; j++) d += Math.abs(jumped[i + j] - played[i + j]);
      if (d > 24) differ++;
    }
    return { differ, pixels: jumped.length / 4 };
  });
  console.log(`the picture at the end, jumped to and played to: ${picture.differ} of ${picture.pixels} pixels differ`);
  check(seen && seen.whole && seen.strokes === 0 && picture.differ <= picture.pixels * 0.001,
        'To the end copies the whole path drawn once after the load, the picture playing draws',
        JSON.stringify({ whole: seen && seen.whole, ...picture }));
  await page.close();

  // ---- run --html of the demo deck, typed with its absolute path
  const htmlFile = path.join(workDir, 'demo-replay.html');
  const h = parsons(['run', deck, '-q', '--html', htmlFile]);
  check(h.status === 0 && fs.existsSync(htmlFile), 'parsons run --html writes the demo deck\'s page', h.stderr);
  const text = fs.readFileSync(htmlFile, 'utf8');
  const bytes = fs.statSync(htmlFile).size;
  console.log(`demo deck --html page: ${bytes} bytes (${(bytes / 1048576).toFixed(2)} MiB; issue: under 1 MB)`);
  check(bytes < 1e6, 'the demo deck\'s --html page is under 1 MB', `${bytes} bytes`);
  check(!text.includes(demoDir) && !text.includes('airfoil-template/') && !text.includes(workDir),
        'the --html page names no folder of the deck\'s path');
  check(/<title>parsons replay: naca2412\.cbn<\/title>/.test(text), 'the --html page\'s title is the deck\'s file name',
        (text.match(/<title>[^<]*<\/title>/) || [''])[0]);
  const replay = await browser.newPage();
  await replay.setViewport(t.SCREENS.laptop);
  watchPage(replay, problems);
  await replay.goto(`file://${htmlFile}`);
  const unpackMs = await replay.evaluate(() => window.parsonsUnpackMs);
  const heading = await replay.evaluate(() => document.body.innerText.includes(document.title.replace(/^.*: /, '')));
  console.log(`the --html page unpacks its record in ${unpackMs.toFixed(1)} ms`);
  check(unpackMs >= 0 && unpackMs < 500, 'the --html record unpacks quickly', `${unpackMs.toFixed(1)} ms`);
  check(heading, 'the --html page shows the deck\'s file name');
  const fromFile = await recordDigest(replay);
  check(JSON.stringify(fromFile) === JSON.stringify(live),
        'the --html record unpacks bit for bit to the record the live page ran',
        JSON.stringify({ page: live, html: fromFile }));
  await replay.click('#to-end');
  await replay.waitForSelector('#run-state[data-finished="true"]');
  compareRun('demo deck --html replay', await pageResult(replay),
             nativeReport(parsonsExe, deck, workDir, 'faster-replay'));
  await t.shot(replay, 'demo-replay');
  await replay.close();
};
