#!/usr/bin/env node
// The exhibit page in a real browser (docs/web.md): Debian's chromium, headless, driven by
// puppeteer-core (tests/js's lockfile; it downloads no browser), the page served from
// localhost by a static server of this script's own.
//
//   node tests/js/browser_test.js SITE_DIR PARSONS_EXE WORK_DIR [NAME...]
//
// SITE_DIR is build-wasm/site (cmake --preset wasm), PARSONS_EXE the native program the page
// is held against, WORK_DIR where the native runs, the --html files, the downloads and the
// screenshots go (kept as artefacts). The checks are the files of tests/js/exhibit/, one a
// capability of the page, run in the order of their names (or only the NAMEs given, e.g.
// `basics`); each exports an async function of the context below and reports through check().
// Across all of them: no console error, page error or failed request anywhere.
// Exit 0 when all holds, 1 otherwise.
'use strict';

const childProcess = require('child_process');
const fs = require('fs');
const path = require('path');
const { startServer, launchChromium, watchPage } = require('./web_support');

if (process.argv.length < 5) {
  console.error('usage: browser_test.js SITE_DIR PARSONS_EXE WORK_DIR [NAME...]');
  process.exit(2);
}
const [site, parsonsExe, workDir] = process.argv.slice(2, 5).map((a) => path.resolve(a));
const only = process.argv.slice(5);
const SOURCE = path.resolve(__dirname, '..', '..');
fs.rmSync(workDir, { recursive: true, force: true });
fs.mkdirSync(workDir, { recursive: true });

let failures = 0;
function check(ok, what, detail = '') {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}${detail ? ': ' + detail : ''}`);
  if (!ok) failures++;
}
function parsons(args, opts = {}) {
  return childProcess.spawnSync(parsonsExe, args, { encoding: 'utf8', ...opts });
}

// The page's end of a run against the native report of the same deck.
function compareRun(name, page, report) {
  // The report gives machine time to the microsecond.
  check(Math.abs(page.seconds - report.machine_seconds) <= 5e-7, `${name}: machine time`,
        `page ${page.seconds}, CLI ${report.machine_seconds}`);
  const reason = report.stop ? report.stop.reason : 'completed';
  check(page.reason === reason, `${name}: stop reason`, `page ${page.reason}, CLI ${reason}`);
  for (const [axis, a] of Object.entries(report.axes)) {
    // The counters read 0.000 .. 9.999 (four decimal stepping switches).
    const thousandths = ((Math.round(a.position * 1000) % 10000) + 10000) % 10000;
    const counters = `${Math.floor(thousandths / 1000)}.${String(thousandths % 1000).padStart(3, '0')}`;
    check(page.axes[axis].counters === counters, `${name}: ${axis} counters`,
          `page ${page.axes[axis].counters}, CLI position ${a.position}`);
    check(page.axes[axis].real === a.real_position.toFixed(5), `${name}: ${axis} real position`,
          `page ${page.axes[axis].real}, CLI ${a.real_position}`);
  }
}

// The screen sizes every capability is looked at on: a laptop and a phone.
const SCREENS = { laptop: { width: 1366, height: 768 }, phone: { width: 390, height: 844, isMobile: true, hasTouch: true, deviceScaleFactor: 2 } };

const checksDir = path.join(__dirname, 'exhibit');
const names = fs.readdirSync(checksDir).filter((f) => f.endsWith('.js')).map((f) => f.replace(/\.js$/, '')).sort();
for (const n of only) {
  if (!names.includes(n)) {
    console.error(`browser_test.js: no check ${n} in ${checksDir} (${names.join(', ')})`);
    process.exit(2);
  }
}

(async () => {
  const server = await startServer(site);
  const browser = await launchChromium(path.join(workDir, 'profile'));
  const problems = [];
  const t = { browser, server, site, parsonsExe, workDir, SOURCE, SCREENS, problems, check, parsons, compareRun };
  // The live page on a screen of SCREENS, watched for errors, once its first view is whole (the
  // sample deck punched, drawn and run: body[data-settled]).
  t.open = async (screen = 'laptop', query = '') => {
    const page = await browser.newPage();
    await page.setViewport(SCREENS[screen]);
    watchPage(page, problems);
    await page.goto(`${server.url}/index.html${query}`);
    await page.waitForSelector('body[data-settled="true"]', { timeout: 30000 });
    return page;
  };
  // The sample deck's `parsons run --html` page, written to WORK_DIR/NAME and opened from disk at
  // a laptop's size, watched for errors, once its record is loaded.
  t.openSampleReplay = async (name) => {
    const html = path.join(workDir, name);
    const r = parsons(['run', path.join(SOURCE, 'decks', 'samples', 'patent-example.csv'), '--html', html, '-q']);
    check(r.status === 0, `parsons run --html of the sample deck (${name})`, r.stderr);
    const replay = await browser.newPage();
    await replay.setViewport(SCREENS.laptop);
    watchPage(replay, problems);
    await replay.goto(`file://${html}`);
    await replay.waitForFunction(() => window.parsonsViewer && window.parsonsViewer.loaded, { timeout: 30000 });
    return replay;
  };
  // A screenshot kept with the others: WORK_DIR/NAME.png (the docs script copies some).
  t.shot = (page, name, fullPage = false) => page.screenshot({ path: path.join(workDir, `${name}.png`), fullPage });
  for (const name of names.filter((n) => only.length === 0 || only.includes(n))) {
    console.log(`---- ${name}`);
    const t0 = Date.now();
    try {
      await require(path.join(checksDir, name))(t);
    } catch (e) {
      check(false, `${name}: the checks ran through`, e.stack || String(e));
    }
    console.log(`---- ${name}: ${((Date.now() - t0) / 1000).toFixed(1)} s`);
  }
  await browser.close();
  server.close();
  check(problems.length === 0, 'no console error, page error or failed request', problems.join('\n'));
  console.log(`screenshots in ${workDir}: ${fs.readdirSync(workDir).filter((f) => f.endsWith('.png')).join(' ')}`);
  console.log(failures === 0 ? 'all browser checks passed' : `${failures} browser check(s) failed`);
  process.exit(failures === 0 ? 0 : 1);
})();
