// The card, read (issue 52, item 2): the card in reader 134 with the record's holes, the first
// bank of brushes passing over it row by row (a hole lights as the bank passes its row), the
// second bank after it; every sensed hole lights the part it picks on the panel, and that part
// is the one the machine closed (its recorded value on once the relays have picked). A hole
// tapped says what it picks. In the live page, on a phone and in the --html replay. Run by
// tests/js/browser_test.js.
'use strict';

// The reader at machine time t: what the view shows, and the panel parts it lit.
function readerAt(page, t) {
  return page.evaluate((t) => {
    const v = window.parsonsViewer;
    v.seek(t);
    const svg = document.querySelector('#reader-view svg.reader');
    if (!svg) return null;
    const holes = [...svg.querySelectorAll('.reader-hole')];
    const lit = [...document.querySelectorAll('#panel .brush-picks')].map((e) => Number(e.dataset.signal));
    const bank1 = svg.querySelector('.bank-1');
    return {
      t: v.t,
      card: svg.dataset.card,
      state: svg.dataset.state,
      holes: holes.length,
      sensed: holes.filter((h) => h.classList.contains('sensed')).length,
      bank1: bank1.getAttribute('visibility'),
      lit,
      // Each sensed hole's part by name, and whether the machine holds it on now.
      picks: holes.filter((h) => h.classList.contains('sensed') && h.dataset.picks).map((h) => h.dataset.picks),
    };
  }, t);
}

async function reads(t, page, where) {
  const { check } = t;
  // The lists shortened to their lengths: a failure's detail stays readable.
  const say = (v) => JSON.stringify(v, (k, x) => (Array.isArray(x) && x.length > 6 ? `${x.length} items` : x));
  // The first card's instants, from the record: the first bank's sensing, the relays' pick.
  const first = await page.evaluate(() => {
    const v = window.parsonsViewer;
    const b = v.h.brushes[0];
    const count = [...b.holes.matchAll(/.../g)].map((m) => parseInt(m[0], 16))
      .reduce((n, w) => n + w.toString(2).split('').filter((c) => c === '1').length, 0);
    const fed = v.reader.fed[0];
    return { t: b.t, fed, count };
  });
  check(first.count > 20 && first.fed < first.t, `${where}: the record holds card 1's holes and when the reader took it`, say(first));
  const fed = await readerAt(page, first.fed + 1e-6);
  check(fed && fed.card === '1' && fed.holes === first.count && fed.sensed === 0 && fed.bank1 === 'visible' && fed.lit.length === 0,
        `${where}: card 1 just fed: every hole of the record drawn, none sensed yet, the first bank at the nine edge`, say(fed));
  const half = await readerAt(page, (first.fed + first.t) / 2);
  check(half.sensed > 0 && half.sensed < half.holes && half.bank1 === 'visible',
        `${where}: halfway through the first bank's pass some rows are sensed, not all`, say(half));
  // The picture: on a laptop the panel and the card under it, on a phone the card.
  await page.evaluate((phone) => document.getElementById(phone ? 'card-reader' : 'cabinet').scrollIntoView(), where === 'phone');
  await t.shot(page, `reader-${where.replace(/[^a-z]+/g, '-')}`);
  // Past the relays' operate time: every hole sensed, and each part a hole names is on the panel,
  // lit, and on in the machine's record.
  const after = await readerAt(page, first.t + 0.02);
  const machine = await page.evaluate((picks) => {
    const v = window.parsonsViewer;
    const id = new Map(v.h.signals.map((s, i) => [`${s.scope}.${s.name}`, i]));
    const relays = picks.filter((p) => /\.relay_\d$|sequence_switch_224/.test(p));
    return { relays: relays.length, off: relays.filter((p) => v.values[id.get(p)] === 0), ids: [...new Set(picks.map((p) => id.get(p)))] };
  }, after.picks);
  check(after.sensed === after.holes && machine.relays > 20 && machine.off.length === 0,
        `${where}: after the first bank every hole is sensed and every relay a hole picks is closed in the record`, say({ after, machine }));
  const litAll = machine.ids.every((i) => after.lit.includes(i));
  check(litAll && after.lit.length > 20, `${where}: every part a sensed hole picks is lit on the panel`, say({ lit: after.lit.length, ids: machine.ids.length }));
  // A hole tapped names its field and the part its brush picks.
  const told = await page.evaluate(() => {
    const hole = [...document.querySelectorAll('#reader-view .reader-hole')].find((h) => /absolute_storage_35/.test(h.dataset.picks || ''));
    hole.scrollIntoView({ block: 'center' });
    const r = hole.getBoundingClientRect(); // a finger's tap a little beside the hole
    hole.dispatchEvent(new MouseEvent('click', { bubbles: true, clientX: r.left + r.width / 2 + 2, clientY: r.top + r.height / 2 + 1 }));
    const part = document.querySelector('#panel .brush-chosen');
    return { says: document.querySelector('#reader-view .reader-says').textContent, picks: hole.dataset.picks,
             chosen: part ? Number(part.dataset.signal) : -1,
             want: window.parsonsViewer.h.signals.findIndex((s) => `${s.scope}.${s.name}` === hole.dataset.picks) };
  });
  check(/Column \d+, row \d .*picks holding relay \d of bank 35\d/.test(told.says) && told.chosen === told.want,
        `${where}: a hole tapped says which relay it picks, and that relay is marked on the panel`, say(told));
  // The next card replaces it.
  const second = await page.evaluate(() => window.parsonsViewer.h.brushes[1].t);
  const next = await readerAt(page, second + 0.001);
  const changed = next.lit.some((i) => !after.lit.includes(i)) || after.lit.some((i) => !next.lit.includes(i));
  check(next.card === '2' && next.holes > 20 && next.sensed === next.holes && changed,
        `${where}: card 2 in the reader, sensed, and the parts its holes pick lit in place of card 1's`, say({ next, changed }));
}

module.exports = async function reader(t) {
  const page = await t.open('laptop');
  await reads(t, page, 'live page');
  await page.close();
  const phone = await t.open('phone');
  await phone.evaluate(() => document.getElementById('card-reader').scrollIntoView());
  await reads(t, phone, 'phone');
  await phone.close();
  const replay = await t.openSampleReplay('reader-replay.html');
  await reads(t, replay, '--html replay');
  await replay.close();
};
