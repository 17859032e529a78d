// After the tour, a next step (issue 52, item 5): "punch your own card". Ending the tour offers
// a short form; "make the table move 2.000 inches" becomes, through `parsons gen gcode`, a card
// in the keypunch, which the page punches, runs and plays: the run ends where the native
// `parsons run` of the same listing ends, the table standing at 2.000 in, the mill with it. A
// move the counters cannot hold is refused in the visitor's words and nothing runs. Run by tests/js/browser_test.js.
'use strict';

const fs = require('fs');
const path = require('path');
const { nativeReport, pageResult } = require('../web_support');

module.exports = async function guide(t) {
  const { check, compareRun, parsonsExe, workDir } = t;
  const say = (v) => JSON.stringify(v);
  const page = await t.open('laptop');
  check(await page.$eval('#next-step', (e) => e.hidden), 'guide: no next step before the tour');
  await page.click('#tour-start');
  await page.waitForSelector('#tour:not([hidden])');
  await page.click('#tour-end');
  const offered = await page.evaluate(() => ({
    shown: !document.getElementById('next-step').hidden,
    focused: document.activeElement && document.activeElement.id,
    words: document.getElementById('next-step').textContent.replace(/\s+/g, ' ').trim().slice(0, 80),
  }));
  check(offered.shown && offered.focused === 'guide-inches', 'guide: the tour ended, the next step is offered', say(offered));

  // The table 2.000 in, punched by the generator and run.
  await page.select('#guide-axis', 'table');
  await page.$eval('#guide-inches', (e) => { e.value = '2.000'; });
  await page.click('#guide-go');
  await page.waitForSelector('#run-state[data-finished="true"]', { timeout: 60000 });
  const listing = await page.$eval('#listing', (e) => e.value);
  const native = t.parsons(['gen', 'gcode', '-', '--to', 'listing', '-o', path.join(workDir, 'guide-native.csv')],
                           { input: 'G20 G90\nG1 X2.000\nM2\n' });
  check(native.status === 0 && /^1,[^,]*,table,\+,\d,[^,]*,[^,]*,2\.000,2\.000,\d$/m.test(listing) &&
        listing.split('\n').filter((l) => /^\d/.test(l)).join('\n') ===
          fs.readFileSync(path.join(workDir, 'guide-native.csv'), 'utf8').split('\n').filter((l) => /^\d/.test(l)).join('\n'),
        'guide: the keypunch holds the card asked for', listing);
  const file = path.join(workDir, 'guide.csv');
  fs.writeFileSync(file, listing);
  const report = nativeReport(parsonsExe, file, workDir, 'guide');
  const result = await pageResult(page);
  compareRun('guide: your own card', result, report);
  const end = await page.evaluate(() => ({
    real: document.querySelector('#positions tr[data-axis="table"] td.real').textContent,
    mill: document.querySelector('#mill svg').dataset.table,
    status: document.getElementById('machine-status').textContent,
  }));
  check(Math.abs(Number(end.real) - 2) < 0.002 && end.mill === end.real && /ran to the end: 1 card/.test(end.status),
        'guide: the table stands at 2.000 in, the mill with it, and the top line says the card ran', say(end));

  // A value parsons refuses: said in the keypunch, nothing runs.
  await page.click('#tour-start');
  await page.click('#tour-end');
  await page.$eval('#guide-inches', (e) => { e.value = '12.5'; });
  await page.click('#guide-go');
  await page.waitForFunction(() => !document.getElementById('deck-error').hidden);
  const refused = await page.evaluate(() => ({
    lead: (document.querySelector('#deck-error .visitor-words') || {}).textContent,
    state: document.getElementById('run-state').textContent,
  }));
  check(/^Your card: that move does not fit: the counters hold 0 to 9\.999 inches/.test(refused.lead || '') && /failed/.test(refused.state),
        'guide: a move the counters cannot hold is refused in the keypunch\'s words', say(refused));
  await page.close();
};
