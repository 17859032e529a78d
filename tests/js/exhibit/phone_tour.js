// On a phone the tour's caption and the part it lights are on one screen (issue 52, defect 6):
// at every stop of the tour of card 1, the caption (a sheet along the screen's foot, its buttons
// in view) and the parts of the cabinet it lights are all inside the viewport, none under the
// caption (or, where the parts lit are spread further than the screen above the caption holds,
// the part the stop is about). Run by tests/js/browser_test.js.
'use strict';

module.exports = async function phoneTour(t) {
  const { check } = t;
  const page = await t.open('phone');
  await page.click('#tour-start');
  await page.waitForSelector('#tour:not([hidden])');
  const stops = await page.evaluate(() => window.parsonsViewer.tour.route.stops.length);
  let shown = 0;
  for (let n = 0; n < stops; n++) {
    if (n > 0) await page.click('#tour-next');
    await page.waitForFunction((k) => document.getElementById('tour').dataset.stop === String(k), {}, n);
    const where = await page.evaluate(() => {
      const box = document.getElementById('tour').getBoundingClientRect();
      // Every part lit, if they fit above the caption together; else the part the stop is about.
      const lit = [...document.querySelectorAll('#panel .tour-here')];
      const part = document.querySelector('#panel [data-tour-main]');
      const rects = lit.map((e) => e.getBoundingClientRect());
      const all = lit.length ? { top: Math.min(...rects.map((r) => r.top)), bottom: Math.max(...rects.map((r) => r.bottom)) } : null;
      const fits = all && all.bottom - all.top <= box.top - 16;
      const p = fits ? all : part ? part.getBoundingClientRect() : null;
      const next = document.getElementById('tour-end').getBoundingClientRect();
      return {
        h: innerHeight,
        nav: [Math.round(next.top), Math.round(next.bottom)],
        caption: [Math.round(box.top), Math.round(box.bottom)],
        part: p ? [Math.round(p.top), Math.round(p.bottom)] : null,
        name: part ? part.getAttribute('aria-label') || part.textContent.trim().slice(0, 40) : '',
        all: !!fits,
      };
    });
    const ok = where.part && where.caption[0] >= 0 && where.caption[1] <= where.h + 1 &&
      where.part[0] >= 0 && where.part[1] <= where.caption[0] &&
      where.nav[0] >= where.caption[0] && where.nav[1] <= where.h + 1; // Back, Next, End in view
    check(ok, `phone: tour stop ${n + 1} of ${stops}: the caption and the part it lights on one screen`, JSON.stringify(where));
    if (ok) shown++;
    if (n === 1) await t.shot(page, 'tour-phone-one-screen');
  }
  check(stops >= 5 && shown === stops, 'phone: every tour stop keeps its caption and its part on one screen', `${shown} of ${stops}`);
  await page.click('#tour-end');
  const ended = await page.evaluate(() => [document.getElementById('tour').hidden, document.body.classList.contains('touring')]);
  check(ended[0] && !ended[1], 'phone: the tour ended, the sheet is gone', JSON.stringify(ended));
  await page.close();
};
