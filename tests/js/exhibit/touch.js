// A finger hits what it means (issue 52, defect 2): on a touch screen (the phone, and a touch
// screen as wide as a laptop) every run control and every panel part is a target of at least
// 44 x 44 CSS px; a bank of holding relays is one target, its whole row, and a tap on the row
// away from any relay tells that bank's story. The laptop with a mouse keeps its dense panel.
// Run by tests/js/browser_test.js.
'use strict';

// Targets smaller than 44 x 44: controls, bank rows, lamps, dials (relays are inside their row).
function smallTargets(page) {
  return page.evaluate(() => {
    const coarse = matchMedia('(pointer: coarse)').matches;
    const sel = '.controls button, #scrub, #panel .bank, #panel .lamp, #panel .dial, #tour-start';
    const all = [...document.querySelectorAll(sel)].filter((e) => e.getClientRects().length);
    const small = all.filter((e) => { const r = e.getBoundingClientRect(); return r.width < 44 || r.height < 44; })
      .map((e) => `${e.id || e.dataset.bank || e.getAttribute('aria-label') || e.className} ${Math.round(e.getBoundingClientRect().width)}x${Math.round(e.getBoundingClientRect().height)}`);
    return { coarse, targets: all.length, small };
  });
}

module.exports = async function touch(t) {
  const { check } = t;
  const say = (v) => JSON.stringify(v);
  const phone = await t.open('phone');
  const p = await smallTargets(phone);
  console.log(`touch, phone: ${p.targets} targets, ${p.small.length} under 44x44 ${p.small.slice(0, 5).join(', ')}`);
  check(p.coarse && p.targets > 100 && p.small.length === 0, 'phone: every control and panel part is at least 44 x 44 CSS px', say(p));

  // A tap on a bank's row, right of its last relay: the bank's story.
  const spot = await phone.evaluate(() => {
    const row = document.querySelector('#panel [data-scope="table"] .bank');
    row.scrollIntoView({ block: 'center' });
    const r = row.getBoundingClientRect();
    const last = [...row.querySelectorAll('.relay')].pop().getBoundingClientRect();
    return { x: Math.round((last.right + r.right) / 2), y: Math.round(r.top + r.height / 2), bank: row.dataset.bank, gap: r.right - last.right };
  });
  check(spot.gap >= 8, 'phone: a bank row reaches past its relays', say(spot));
  await phone.touchscreen.tap(spot.x, spot.y);
  await phone.waitForFunction(() => !document.getElementById('part-info').hidden, { timeout: 5000 });
  const story = await phone.$eval('#part-info h3', (e) => e.textContent);
  check(/storage bank 350/.test(story), 'phone: a tap on the bank row away from its relays tells the bank\'s story', story);
  await phone.close();

  // The laptop with a mouse: the dense panel stays (its relays 12 px).
  const laptop = await t.open('laptop');
  const dense = await laptop.evaluate(() => ({
    coarse: matchMedia('(pointer: coarse)').matches,
    relay: Math.round(document.querySelector('#panel .relay').getBoundingClientRect().height),
  }));
  check(!dense.coarse && dense.relay <= 14, 'laptop: the dense panel stays', say(dense));
  await laptop.close();
};
