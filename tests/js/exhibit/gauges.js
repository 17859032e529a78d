// Every view is a function of the instant shown, whichever way it was reached (issue 52,
// defect 1): the side gauges (vertical slide, swivel and tilt angles) beside the machine agree
// with the positions table under it after playing, after a jump back, after *From the start*
// and after a jump to an instant before the first motion, in the live page and in the
// `parsons run --html` replay that opens from disk. Run by tests/js/browser_test.js.
'use strict';


// The gauges and the positions table as the visitor reads them, at the instant shown.
function readViews(page) {
  return page.evaluate(() => {
    const text = (sel) => (document.querySelector(sel) || {}).textContent || '';
    const cell = (axis, cls) => text(`#positions tr[data-axis="${axis}"] td.${cls}`);
    return {
      t: Number(document.getElementById('machine-time').dataset.seconds),
      gauge: {
        vertical: text('#side-gauges [data-gauge="vertical"]'),
        swivel: text('#side-gauges [data-gauge="swivel"]'),
        tilt: text('#side-gauges [data-gauge="tilt (sine plate)"]'),
      },
      table: { vertical: cell('vertical', 'real'), swivel: cell('swivel', 'angle'), tilt: cell('tilt', 'angle') },
    };
  });
}

// The gauge shows the table's number to its own decimals (3 for inches, 2 for degrees).
function agree(v) {
  const num = (s) => (s === '' ? NaN : Number(s.replace(/[^0-9.+-eE]/g, '')));
  const close = (g, t, decimals) => {
    if (t === '') return g === ''; // no record at or before the instant: both say nothing
    return g !== '' && Math.abs(num(g) - num(t)) <= 0.5 * 10 ** -decimals + 1e-9;
  };
  return close(v.gauge.vertical, v.table.vertical, 3) && close(v.gauge.swivel, v.table.swivel, 2) &&
    close(v.gauge.tilt, v.table.tilt, 2);
}

async function jumpsAgree(t, page, where) {
  const { check } = t;
  const say = (v) => JSON.stringify(v);
  // To the end: the gauges stand where the run ended.
  await page.evaluate(() => window.parsonsViewer.seek(window.parsonsViewer.finish));
  const end = await readViews(page);
  check(agree(end) && end.gauge.vertical !== '', `${where}: at the end the gauges agree with the positions table`, say(end));
  // From the start: the deck's start, not the end left behind.
  await page.evaluate(() => document.getElementById('restart').click());
  const start = await readViews(page);
  check(start.t === 0 && agree(start) && start.gauge.vertical !== '',
        `${where}: From the start puts the gauges where the axes start`, say(start));
  // A jump back to 0.160 s, before the first axis moves, from far into the run.
  await page.evaluate(() => { const v = window.parsonsViewer; v.seek(v.finish * 0.6); });
  const mid = await readViews(page);
  check(mid.gauge.vertical !== start.gauge.vertical && mid.gauge.tilt !== start.gauge.tilt,
        `${where}: far into the run the gauges stand elsewhere than at the start`, `${say(start)} ${say(mid)}`);
  await page.evaluate(() => window.parsonsViewer.seek(0.16));
  const back = await readViews(page);
  check(agree(mid) && agree(back) && back.gauge.vertical === start.gauge.vertical &&
        back.gauge.swivel === start.gauge.swivel && back.gauge.tilt === start.gauge.tilt,
        `${where}: a jump back to 0.160 s shows the start again on the gauges`, `${say(mid)} ${say(back)}`);
}

module.exports = async function gauges(t) {
  const { check } = t;

  // ---- the live page: play at 100x, pause, then jump about
  const page = await t.open('laptop');
  await page.click('.speeds [data-speed="100"]');
  await page.click('#play');
  await new Promise((r) => setTimeout(r, 2000));
  await page.click('#pause');
  const played = await readViews(page);
  check(played.t > 1 && agree(played), 'live page: after playing, the gauges agree with the positions table',
        JSON.stringify(played));
  await jumpsAgree(t, page, 'live page');
  await page.close();

  // ---- the --html replay, from disk
  const replay = await t.openSampleReplay('gauges-replay.html');
  await jumpsAgree(t, replay, '--html replay');
  await replay.close();
};
