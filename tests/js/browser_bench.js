#!/usr/bin/env node
// The exhibit page's figures (docs/performance.md, docs/web.md), median of 5 each:
//   - the demo deck "to the end" in the page: from the press of the button to the finished view
//     (the wasm run with every signal change recorded, the copy of the record, the replay to its
//     end and the drawing), against the native CLI running the same deck: report only, and
//     recording every change (--events, what the page records);
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

function timeNative(args) {
  const times = [];
  for (let i = 0; i < RUNS; i++) {
    const t0 = process.hrtime.bigint();
    const r = childProcess.spawnSync(parsonsExe, args, { encoding: 'utf8' });
    times.push(Number(process.hrtime.bigint() - t0) / 1e6);
    if (r.status !== 0) throw new Error(`parsons ${args.join(' ')}: ${r.stderr}`);
  }
  return median(times);
}

(async () => {
  const demoDir = path.join(workDir, 'demo');
  const d = childProcess.spawnSync(parsonsExe, ['demo', '--out', demoDir], { encoding: 'utf8' });
  if (d.status !== 0) throw new Error(`parsons demo: ${d.stderr}`);
  const deck = path.join(demoDir, 'naca2412.cbn');
  const nativePlain = timeNative(['run', deck, '-q', '--report', path.join(workDir, 'r.json')]);
  const nativeEvents = timeNative(['run', deck, '-q', '--report', path.join(workDir, 'r.json'),
                                   '--events', path.join(workDir, 'e.jsonl')]);

  const server = await startServer(site);
  const browser = await launchChromium(path.join(workDir, 'profile'));
  const toEnd = [];
  const wasmRun = [];
  const ready = [];
  try {
    for (let i = 0; i < RUNS; i++) {
      const page = await browser.newPage();
      const errors = [];
      page.on('pageerror', (e) => errors.push(e.message));
      await page.goto(`${server.url}/index.html`);
      await page.waitForSelector('#machine-status[data-state="ready"]', { timeout: 30000 });
      ready.push(await page.evaluate(() => window.parsonsReadyAt));
      await page.click('#load-demo');
      await page.waitForFunction(() => document.querySelectorAll('#cards img').length > 50);
      await page.click('#to-end');
      await page.waitForSelector('#run-state[data-finished="true"]');
      const timing = await page.evaluate(() => window.parsonsTiming);
      if (errors.length) throw new Error(errors.join('\n'));
      toEnd.push(timing.toEndMs);
      wasmRun.push(timing.runMs);
      await page.close();
    }
  } finally {
    await browser.close();
    server.close();
  }
  const page = median(toEnd);
  const wasm = fs.statSync(path.join(site, 'parsons_web.wasm')).size;
  const js = fs.statSync(path.join(site, 'parsons_web.js')).size;
  console.log(`demo deck (NACA 2412, ${RUNS} runs, medians):`);
  console.log(`  native CLI, report only            ${nativePlain.toFixed(1)} ms (whole process)`);
  console.log(`  native CLI, every change recorded  ${nativeEvents.toFixed(1)} ms (--events)`);
  console.log(`  page, "to the end"                 ${page.toFixed(1)} ms (of which the wasm run ${median(wasmRun).toFixed(1)} ms)`);
  console.log(`  page / native                      ${(page / nativePlain).toFixed(2)}x report only, ` +
              `${(page / nativeEvents).toFixed(2)}x recording`);
  console.log(`first view interactive               ${median(ready).toFixed(0)} ms after navigation`);
  console.log(`parsons_web.wasm                     ${wasm} bytes (${(wasm / 1048576).toFixed(2)} MiB), parsons_web.js ${js} bytes`);
})().catch((e) => {
  console.error(e.stack || String(e));
  process.exit(1);
});
