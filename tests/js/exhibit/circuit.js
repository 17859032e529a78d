// Signals you can watch travel (issue 52, item 3): one axis's circuit after Figs. 10-12. Each
// part is lit exactly while the record holds one of its signals on (checked part by part at the
// start, at the first slow-down, halfway and at the end); played at 1x across a slow-down, the
// wires light as the changes arrive (commutator to counters at every impulse, relay 256 to speed
// switch 236 at the step down) and go dark after; the tour's stops light the paths they tell;
// another axis can be followed. In the live page, on a phone and in the --html replay. Run by
// tests/js/browser_test.js.
'use strict';

// Every part's lamp against the record's values now: the parts that disagree.
function disagreeing(page) {
  return page.evaluate(() => {
    const v = window.parsonsViewer;
    const bad = [];
    for (const g of document.querySelectorAll('#circuit-view .circuit-part')) {
      const ids = g.dataset.signals ? g.dataset.signals.split(' ').map(Number) : [];
      const on = ids.some((i) => v.values[i] !== 0);
      if (on !== g.classList.contains('on')) bad.push(g.dataset.part);
    }
    return bad;
  });
}

async function follows(t, page, where, shots) {
  const { check } = t;
  const say = (v) => JSON.stringify(v);
  const axis = await page.evaluate(() => document.querySelector('#circuit-view svg.circuit').dataset.axis);
  check(axis === 'table', `${where}: the circuit drawn follows the table at first`, axis);
  // The first slow-down of the table: its stepping relay 256 picking, from the record.
  const slow = await page.evaluate(() => {
    const v = window.parsonsViewer;
    const id = v.h.signals.findIndex((s) => s.scope === 'table' && s.name === 'stepping_relay_256');
    const k = v.a.change_id.findIndex((x, i) => x === id && v.a.change_v[i] === 1);
    return v.a.change_t[k];
  });
  for (const at of [0, slow, 'half', 'end']) {
    await page.evaluate((at) => {
      const v = window.parsonsViewer;
      if (at === 'end') v.toEnd(); else v.seek(at === 'half' ? v.finish / 2 : at);
    }, at);
    const bad = await disagreeing(page);
    check(bad.length === 0, `${where}: at ${at} every part is lit exactly while the record holds its signal on`, say(bad));
  }
  // Played at 1x from just before the slow-down: the wires light as the changes come.
  const seen = await page.evaluate(async (slow) => {
    const v = window.parsonsViewer;
    v.seek(slow - 0.15);
    v.chooseSpeed('1');
    v.play(slow + 0.1);
    const lit = new Set();
    let most = 0;
    while (v.playing) {
      await new Promise((r) => requestAnimationFrame(r));
      const live = [...document.querySelectorAll('#circuit-view .circuit-wire.live')].map((w) => w.dataset.wire);
      live.forEach((w) => lit.add(w));
      most = Math.max(most, live.length);
    }
    return { lit: [...lit], most, t: v.t };
  }, slow);
  check(seen.lit.includes('comm-counters') && seen.lit.includes('r256-s236') && seen.lit.includes('ch257-r256'),
        `${where}: played at 1x across the slow-down, the impulses light commutator → counters, and the step lights channel 257 → relay 256 → speed switch 236`, say(seen));
  check(!seen.lit.includes('z292-inccount') && !seen.lit.includes('z292-abs'),
        `${where}: the zeroizing circuit's wires stay dark while the counters count (it is off)`, say(seen));
  if (shots) await t.shot(page, shots.travel);
  await new Promise((r) => setTimeout(r, 700));
  const dark = await page.evaluate(() => document.querySelectorAll('#circuit-view .circuit-wire.live').length);
  check(dark === 0, `${where}: paused, the wires go dark`, String(dark));
  // The tour: each stop lights the path it tells; the end of the tour puts it out.
  const tour = await page.evaluate(() => {
    const v = window.parsonsViewer;
    v.tour.start();
    const out = [];
    for (let n = 0; n < v.tour.route.stops.length; n++) {
      v.tour.show(n);
      const svg = document.querySelector('#circuit-view svg.circuit');
      const lit = [...svg.querySelectorAll('.circuit-wire.path')].map((w) => w.dataset.wire).sort();
      out.push({ title: v.tour.route.stops[n].title, want: [...v.tour.route.stops[n].path].sort(), lit, axis: svg.dataset.axis, route: v.tour.route.axis });
    }
    return out;
  });
  const wrong = tour.filter((s) => s.lit.length === 0 || s.lit.join() !== s.want.join() || s.axis !== s.route);
  check(tour.length >= 8 && wrong.length === 0, `${where}: every tour stop lights its path in the circuit of the axis it follows`, say(wrong.length ? wrong : tour.length));
  const slowing = tour.findIndex((s) => /comparer slows/.test(s.title));
  await page.evaluate((n) => window.parsonsViewer.tour.show(n), slowing);
  if (shots) {
    await page.evaluate(() => document.getElementById('circuit-view').scrollIntoView({ block: 'start' }));
    await t.shot(page, shots.tour);
  }
  const ended = await page.evaluate(() => {
    window.parsonsViewer.tour.end();
    return document.querySelectorAll('#circuit-view .circuit-wire.path').length;
  });
  check(ended === 0, `${where}: the tour's end puts its path out`, String(ended));
  // Another axis followed.
  const cross = await page.evaluate(() => {
    const s = document.getElementById('circuit-axis');
    s.value = 'cross';
    s.dispatchEvent(new Event('change'));
    const v = window.parsonsViewer;
    const g = document.querySelector('#circuit-view [data-part="r256"]');
    const ids = g.dataset.signals.split(' ').map(Number);
    return { axis: document.querySelector('#circuit-view svg.circuit').dataset.axis, names: ids.map((i) => `${v.h.signals[i].scope}.${v.h.signals[i].name}`) };
  });
  check(cross.axis === 'cross' && cross.names.join() === 'cross.stepping_relay_256', `${where}: the cross slide's circuit, its own relay 256`, say(cross));
  const bad = await disagreeing(page);
  check(bad.length === 0, `${where}: the cross slide's parts lit as the record holds them`, say(bad));
  // A part clicked tells its story, as the panel's part does.
  const story = await page.evaluate(() => {
    document.querySelector('#circuit-view [data-part="s236"]').dispatchEvent(new MouseEvent('click', { bubbles: true }));
    const info = document.getElementById('part-info');
    return { hidden: info.hidden, text: info.textContent.slice(0, 120) };
  });
  check(!story.hidden && /236/.test(story.text), `${where}: speed switch 236 clicked in the circuit tells its story`, say(story));
}

module.exports = async function circuit(t) {
  const page = await t.open('laptop');
  await page.evaluate(() => document.getElementById('circuit').scrollIntoView({ block: 'end' }));
  await follows(t, page, 'live page', { travel: 'circuit-travel', tour: 'circuit-tour' });
  await page.close();
  const phone = await t.open('phone');
  await phone.evaluate(() => document.getElementById('circuit').scrollIntoView({ block: 'end' }));
  await follows(t, phone, 'phone', { travel: 'circuit-phone', tour: 'circuit-tour-phone' });
  await phone.close();
  const replay = await t.openSampleReplay('circuit-replay.html');
  await follows(t, replay, '--html replay');
  await replay.close();
};
