// The top line says what the machine is doing (issue 52, defect 3), not "ready … Press Play"
// whatever happens: ready, running, paused, the tour's stop, the end of a run, a machine stop
// (the visitor's words, the exact ones under the controls), a deck that cannot run and a load
// that failed. Run by tests/js/browser_test.js.
'use strict';

const path = require('path');
const { badCbn: makeBadCbn } = require('../web_support');

const statusOf = (page) => page.evaluate(() => {
  const s = document.getElementById('machine-status');
  return { state: s.dataset.state, text: s.textContent };
});

module.exports = async function status(t) {
  const { check, workDir, SOURCE } = t;
  const say = (s) => JSON.stringify(s);
  const page = await t.open('laptop');
  const ready = await statusOf(page);
  check(ready.state === 'ready' && /ready/.test(ready.text) && /Press Play/.test(ready.text),
        'status: ready on the first view', say(ready));

  // Running, then paused.
  await page.click('.speeds [data-speed="100"]');
  await page.click('#play');
  await page.waitForFunction(() => Number(document.getElementById('machine-time').dataset.seconds) > 2);
  const running = await statusOf(page);
  check(running.state === 'running' && /^Running: card \d+ in the reader/.test(running.text),
        'status: running while it plays, with the card in the reader', say(running));
  await page.click('#pause');
  const paused = await statusOf(page);
  check(paused.state === 'paused' && /^Paused at \d+\.\d{3} s/.test(paused.text), 'status: paused', say(paused));

  // The tour: its stop, then back to the run's own state when it ends.
  await page.click('#tour-start');
  await page.waitForSelector('#tour:not([hidden])');
  const tour1 = await statusOf(page);
  await page.click('#tour-next');
  const tour2 = await statusOf(page);
  check(tour1.state === 'tour' && /stop 1 of \d+/.test(tour1.text) && /stop 2 of \d+/.test(tour2.text),
        'status: the tour says its stop, and follows Next', `${say(tour1)} ${say(tour2)}`);
  await page.click('#tour-end');
  const afterTour = await statusOf(page);
  check(afterTour.state !== 'tour' && !/Tour/.test(afterTour.text), 'status: the tour ended, the line says the run again',
        say(afterTour));

  // The end of a run that completes.
  await page.click('#to-end');
  await page.waitForSelector('#run-state[data-finished="true"]');
  const done = await statusOf(page);
  check(done.state === 'completed' && /ran to the end: 4 cards/.test(done.text), 'status: completed, with its cards',
        say(done));

  // A machine stop: card 2's table check one tenth short, so the counters disagree at the stop.
  await page.evaluate(() => { const d = document.getElementById('deck-drawer'); if (d) d.open = true; });
  await page.evaluate(() => {
    const l = document.getElementById('listing');
    l.value = l.value.replace('2,0,table,-,1,8.585,8.485,8.385,0.600,12', '2,0,table,-,1,8.585,8.485,8.385,0.500,12');
    l.dispatchEvent(new Event('input', { bubbles: true }));
  });
  await new Promise((r) => setTimeout(r, 700)); // the keypunch punches 250 ms after typing stops
  await page.click('#to-end');
  await page.waitForFunction(() => document.getElementById('run-state').dataset.finished === 'true' &&
                             document.getElementById('machine-status').dataset.state !== 'completed',
                             { timeout: 20000 });
  const stopped = await statusOf(page);
  const exact = await page.$eval('#stop-message', (e) => (e.hidden ? '' : e.textContent));
  check(stopped.state === 'stopped' && /^The machine stopped itself on card 2 \(table\): an axis's two counters disagreed/.test(stopped.text) &&
        /machine stop: check_mismatch/.test(exact),
        'status: a machine stop in the visitor\'s words, the exact words under the controls', `${say(stopped)} | ${exact}`);

  // From the start after the stop: ready again, not "stopped".
  await page.click('#restart');
  const again = await statusOf(page);
  check(again.state === 'ready', 'status: From the start after a stop says ready', say(again));

  // A load that fails: the keypunch keeps its deck and the line says so.
  const bad = makeBadCbn(t.parsonsExe, path.join(SOURCE, 'decks', 'samples', 'patent-example.csv'), workDir, 'status bad.cbn');
  await (await page.$('#load-file')).uploadFile(bad);
  await page.waitForSelector('#deck-error:not([hidden])');
  const failed = await statusOf(page);
  check(failed.state === 'load-failed' && /did not load/.test(failed.text) && /kept its deck/.test(failed.text),
        'status: a failed load says so', say(failed));
  // Play runs the deck kept: the line follows the run again.
  await page.click('#to-end');
  await page.waitForSelector('#run-state[data-finished="true"]');
  const kept = await statusOf(page);
  check(kept.state === 'stopped' || kept.state === 'completed', 'status: after a failed load, the kept deck runs and the line says how it ended',
        say(kept));
  await page.close();
};
