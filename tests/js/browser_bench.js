#!/usr/bin/env node
// The exhibit page's figures (docs/performance.md, docs/web.md), median of 5 each:
//   - the demo deck "to the end" in the page: from the press of the button to the finished view
//     (the cabinet, the positions and the picture drawn), pressed first after the page loads (a
//     fresh page each time) and pressed again in the same page (the deck loaded anew each
//     time); the page runs a deck in a task of its own once it is punched (web/exhibit.js,
//     runSoon), so the press finds it run: that run (the wasm run with every signal change
//     recorded, the copy of the record and the view loaded) is printed too, and the press that
//     comes with the load, before that run (the press runs the deck itself); against the native
//     CLI running the same deck: report only, and recording every change (--trace, the compact
//     record; --events, the JSON one);
//   - the first view: from navigation to the page ready for a visitor (the module compiled, the
//     sample deck punched and drawn);
//   - the size of parsons_web.wasm and parsons_web.js.
//
//   node tests/js/browser_bench.js SITE_DIR PARSONS_EXE WORK_DIR [RUNS]
'use strict';

const childProcess = require('child_process');
const fs = require('fs');
const path = require('path');
const { startServer, launchChromium } = require('./web_support');

const [site, parsonsExe, workDir, runsArg] = process.argv.slice(2);
if (!site || !parsonsExe || !workDir) {
  console.error('usage: browser_bench.js SITE_DIR PARSONS_EXE WORK_DIR [RUNS]');
  process.exit(2);
}
const RUNS = Number(runsArg || 5);
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
fs.mkdirSync(workDir, { recursive: true });

// The whole process, less what starting any process from here costs (/bin/true timed the same
// way), median of 2 * RUNS + 1.
function spawnMs(exe, args) {
  const times = [];
  for (let i = 0; i < 2 * RUNS + 1; i++) {
    const t0 = process.hrtime.bigint();
    const r = childProcess.spawnSync(exe, args, { encoding: 'utf8' });
    times.push(Number(process.hrtime.bigint() - t0) / 1e6);
    if (r.status !== 0) throw new Error(`${exe} ${args.join(' ')}: ${r.stderr}`);
  }
  return median(times);
}
let spawnOverhead = null;
function timeNative(args) {
  if (spawnOverhead === null) spawnOverhead = spawnMs('/bin/true', []);
  return spawnMs(parsonsExe, args) - spawnOverhead;
}

(async () => {
  const demoDir = path.join(workDir, 'demo');
  const d = childProcess.spawnSync(parsonsExe, ['demo', '--out', demoDir], { encoding: 'utf8' });
  if (d.status !== 0) throw new Error(`parsons demo: ${d.stderr}`);
  const deck = path.join(demoDir, 'airfoil-template', 'naca2412.cbn');
  const report = ['run', deck, '-q', '--report', path.join(workDir, 'r.json')];
  const nativePlain = timeNative(report);
  const nativeTrace = timeNative([...report, '--trace', path.join(workDir, 't.vcd')]);
  const nativeEvents = timeNative([...report, '--events', path.join(workDir, 'e.jsonl')]);

  const server = await startServer(site);
  const browser = await launchChromium(path.join(workDir, 'profile'));
  const first = [];
  const firstRun = [];
  const firstLoad = [];
  const again = [];
  const ready = [];
  const settled = []; // the cabinet standing at the sample deck's first card
  const withLoad = [];
  const toEnd = async (page) => {
    // A fresh deck, run by the page once punched; the press then finds it run. The button waits
    // in the keypunch's drawer, closed on the first view, so it is pressed as the DOM presses it.
    await page.$eval('#load-demo', (b) => b.click());
    await page.waitForFunction(() => document.querySelectorAll('#cards figure').length > 50);
    await page.waitForSelector('#run-state[data-ran="true"]');
    const run = await page.evaluate(() => ({ ...window.parsonsTiming }));
    await page.click('#to-end');
    await page.waitForSelector('#run-state[data-finished="true"]');
    const press = await page.evaluate(() => window.parsonsTiming);
    if (run.runOnPress || press.runOnPress) throw new Error('the deck was run by the press, not after its load');
    return { ...run, toEndMs: press.toEndMs };
  };
  // The deck loaded and To the end pressed in one task: the press runs the deck itself.
  const loadAndPress = async (page) => {
    await page.evaluate(() => {
      document.getElementById('load-demo').click();
      document.getElementById('to-end').click();
    });
    await page.waitForSelector('#run-state[data-finished="true"]');
    const timing = await page.evaluate(() => window.parsonsTiming);
    if (!timing.runOnPress) throw new Error('the press found the deck run');
    return timing.toEndMs;
  };
  try {
    // A fresh page each time: the first press after the page loads.
    for (let i = 0; i < RUNS; i++) {
      const page = await browser.newPage();
      const errors = [];
      page.on('pageerror', (e) => errors.push(e.message));
      await page.goto(`${server.url}/index.html`);
      await page.waitForSelector('#machine-status[data-state="ready"]', { timeout: 30000 });
      ready.push(await page.evaluate(() => window.parsonsReadyAt));
      await page.waitForSelector('body[data-settled="true"]', { timeout: 30000 });
      settled.push(await page.evaluate(() => window.parsonsSettledAt));
      const timing = await toEnd(page);
      first.push(timing.toEndMs);
      firstRun.push(timing.runMs);
      firstLoad.push(timing.loadMs);
      // Then pressed again, as a visitor does: the deck loaded anew and run again each time.
      for (let k = 0; k < RUNS; k++) again.push((await toEnd(page)).toEndMs);
      withLoad.push(await loadAndPress(page));
      if (errors.length) throw new Error(errors.join('\n'));
      await page.close();
    }
  } finally {
    await browser.close();
    server.close();
  }
  const wasm = fs.statSync(path.join(site, 'parsons_web.wasm')).size;
  const js = fs.statSync(path.join(site, 'parsons_web.js')).size;
  const f = median(first);
  const a = median(again);
  const o = spawnOverhead;
  const row = (what, ms, whole) => console.log(`  ${what.padEnd(46)}${ms.toFixed(1).padStart(6)} ms` +
    (whole ? `   (whole process ${(ms + o).toFixed(1)} ms)` : ''));
  console.log(`demo deck (NACA 2412, ${RUNS} runs each, medians; native: the process less ` +
              `${o.toFixed(1)} ms of starting one, /bin/true timed the same way):`);
  row('native CLI, report only', nativePlain, true);
  row('native CLI, every change recorded (--trace)', nativeTrace, true);
  row('native CLI, every change as JSON (--events)', nativeEvents, true);
  row('page: the demo deck run once punched', median(firstRun) + median(firstLoad));
  row('  of which the WebAssembly run', median(firstRun));
  row('  of which the record copied and the view loaded', median(firstLoad));
  row('page "to the end", first press after loading', f);
  row('page "to the end", pressed again', a);
  row('page "to the end" pressed with the load (runs it)', median(withLoad));
  const ratio = (page, native) => `${(page / native).toFixed(2)}x`;
  console.log(`  page / native report only: first press ${ratio(f, nativePlain)} ` +
              `(whole process ${ratio(f, nativePlain + o)}), again ${ratio(a, nativePlain)} ` +
              `(${ratio(a, nativePlain + o)})`);
  const w = median(withLoad);
  console.log(`  pressed with the load / native report only: ${ratio(w, nativePlain)} ` +
              `(whole process ${ratio(w, nativePlain + o)})`);
  console.log(`  page / native --trace:     first press ${ratio(f, nativeTrace)} ` +
              `(whole process ${ratio(f, nativeTrace + o)}), again ${ratio(a, nativeTrace)} ` +
              `(${ratio(a, nativeTrace + o)})`);
  console.log(`first view interactive: ${median(ready).toFixed(0)} ms after navigation; ` +
              `the cabinet standing at card 1: ${median(settled).toFixed(0)} ms`);
  console.log(`parsons_web.wasm ${wasm} bytes (${(wasm / 1048576).toFixed(2)} MiB), parsons_web.js ${js} bytes`);
})().catch((e) => {
  console.error(e.stack || String(e));
  process.exit(1);
});
