// It teaches the card cycle (issue 31, item 3; docs/web.md): the tour of one card stops at the
// recorded instants of reader, storage, speed switch, comparer and relay 256, delay 258, the stop
// and its lamps, shaft 280 and zeroizing, each with plain words, the patent's passage and figure
// and the part lit; 0.01x and 0.1x; one relay event a press; the time slider; a part clicked,
// tapped or pressed tells its numeral, passage and state; the --html replay has the tour too.
'use strict';

const fs = require('fs');
const path = require('path');
const { watchPage } = require('../web_support');

// The tour's stops on card 1 of the patent's example deck, in order: the numeral each caption is
// about and the recorded signal change that marks it (scope, name, new value or any).
const ROUTE = [
  ['134', 'cabinet', /^card_reader_134\.reading$/, 1],
  ['350', 'table', /^absolute_storage_35\d\.relay_\d$/, 1],
  ['318', 'table', /^incremental_storage_3(18|20|22|24)\.relay_\d$/, 1],
  ['236', 'table', /^speed_switch_236$/, null],
  ['256', 'table', /^stepping_relay_256$/, 1],
  ['258', 'table', /^delay_device_258$/, 1],
  ['270', 'table', /^speed_switch_236$/, 0],
  ['280', 'cabinet', /^stepping_shaft_280$/, null],
  ['292', 'cabinet', /^zeroizing_circuit_292$/, 1],
];
// The patent's text, where the project's workplace keeps it (../shared/seeds beside the
// project): when it is there, every quoted passage is checked word for word against it.
const PATENT_FILE = path.join(__dirname, '..', '..', '..', '..', 'shared', 'seeds', '003_b945df8e233567c4.txt');
const PATENT = fs.existsSync(PATENT_FILE) ? fs.readFileSync(PATENT_FILE, 'utf8') : null;
const inPatent = (text) => PATENT === null || PATENT.includes(text);

module.exports = async function teach(t) {
  const { check, parsons, workDir, SOURCE } = t;
  if (PATENT === null) console.log(`${PATENT_FILE} not found: the passages are not compared with the patent's text`);
  const page = await t.open('laptop');
  const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

  // ---- the tour of card 1
  await page.click('#tour-start');
  const seen = [];
  for (let n = 0; n < ROUTE.length; n++) {
    const stop = await page.evaluate(() => {
      const v = window.parsonsViewer;
      const box = document.getElementById('tour');
      const s = v.tour.route.stops[Number(box.dataset.stop)];
      const sig = v.h.signals[v.a.change_id[s.change]];
      const lit = [...document.querySelectorAll('#panel .tour-here')].map((e) =>
        `${e.closest('[data-scope]').dataset.scope}.${e.dataset.name || e.dataset.bank}`);
      return { n: Number(box.dataset.stop), numeral: box.dataset.numeral, change: s.change, t: v.t,
               changeT: v.a.change_t[s.change], scope: sig.scope, name: sig.name, value: v.a.change_v[s.change],
               caption: box.textContent, quote: box.querySelector('blockquote').textContent, lit, hidden: box.hidden };
    });
    seen.push(stop);
    const [numeral, scope, name, value] = ROUTE[n];
    check(!stop.hidden && stop.n === n && stop.numeral === numeral, `tour stop ${n + 1} is about ${numeral}`, `${stop.numeral}`);
    check(stop.scope === scope && name.test(stop.name) && (value === null || stop.value === value),
          `tour stop ${n + 1}: the recorded change is ${scope} ${name}`, `${stop.scope}.${stop.name} -> ${stop.value}`);
    check(stop.t === stop.changeT, `tour stop ${n + 1}: the machine stands at that change's instant`, `${stop.t} s, change at ${stop.changeT} s`);
    const passage = stop.quote.replace(/^“|”$/g, '');
    check(stop.caption.includes(numeral) && /Figs?\. \d/.test(stop.caption) && passage.length > 40 && inPatent(passage),
          `tour stop ${n + 1}: the caption names ${numeral}, a figure, and quotes the patent word for word`, passage.slice(0, 60));
    check(stop.lit.length > 0 && stop.lit.every((p) => p.startsWith(`${scope}.`)), `tour stop ${n + 1}: its part is lit on the panel`, stop.lit.join(' '));
    if (n === 0) await t.shot(page, 'tour-laptop');
    if (n + 1 < ROUTE.length) await page.click('#tour-next');
  }
  // Each stop is the first such change after the stop before: no recorded change of the kind lies
  // between two stops.
  const firsts = await page.evaluate((route, stops) => {
    const v = window.parsonsViewer;
    let from = stops[0].change;
    return stops.map((s, n) => {
      const [, scope, source, value] = route[n];
      const re = new RegExp(source);
      let early = -1;
      for (let k = from; k < s.change && early < 0; k++) {
        const sig = v.h.signals[v.a.change_id[k]];
        if (sig.scope !== scope || !re.test(sig.name)) continue;
        const nv = v.a.change_v[k];
        // A stop on a value; the speed switch leaving off; the shaft's any step.
        if (value !== null ? nv === value : sig.name === 'stepping_shaft_280' || (v.valueBefore(k) === 0 && nv !== 0)) early = k;
      }
      from = s.change + 1;
      return early;
    });
  }, ROUTE.map(([a, b, re, d]) => [a, b, re.source, d]), seen);
  check(firsts.every((k) => k === -1), 'each tour stop is the first such change after the stop before', JSON.stringify(firsts));
  await page.click('#tour-back');
  check(await page.$eval('#tour', (e) => e.dataset.stop), 'Back goes to the stop before', String(ROUTE.length - 2));
  await page.click('#tour-end');
  check(await page.$eval('#tour', (e) => e.hidden) && (await page.$$('#panel .tour-here')).length === 0,
        'End the tour hides the caption and unlights the parts');

  // ---- a part clicked: bank 352 of the table at the storage stop holds relays 7, 8 and 9, the
  // tenths of 8.785, 8.885 and 8.985, as the patent's own example says
  await page.evaluate((tt) => window.parsonsViewer.seek(tt), seen[2].t);
  await page.click('#panel [data-scope="table"] [data-bank="absolute_storage_352"] .relay');
  const bank = await page.$eval('#part-info', (e) => ({ text: e.textContent, hidden: e.hidden }));
  check(!bank.hidden && /352/.test(bank.text) && /slow-down/.test(bank.text) && !/the stop digit/.test(bank.text),
        'bank 352 says it holds the digits of the slow-down points and the stop', bank.text.slice(0, 160));
  check(/relays 7, 8, 9 closed/.test(bank.text), 'bank 352 shows relays 7, 8 and 9 closed, as the patent\'s example', bank.text.slice(-80));
  check(/Fig\. 12/.test(bank.text) && /An impulse over channel 360 will cause relays Nos\. 7, 8 and 9 in bank 352 to close/.test(bank.text),
        'bank 352 quotes the patent\'s passage of Fig. 12');
  // The incremental banks hold the check number, thousandths in 318 and inches in 324 (Fig. 11's
  // 0.485), as relaylogic/storage.cpp wires them; the counters 310 (thousandths) to 316 (inches).
  const inc = await page.$$eval('#panel [data-scope="table"] [data-bank^="incremental_storage_3"], #panel [data-scope="table"] [data-name^="increment_counter_3"]',
                                (b) => Object.fromEntries(b.map((e) => [e.dataset.bank || e.dataset.name, e.getAttribute('title')])));
  check(/thousandths/.test(inc.incremental_storage_318) && /inches/.test(inc.incremental_storage_324) &&
        /thousandths/.test(inc.increment_counter_310) && /inches/.test(inc.increment_counter_316) &&
        Object.entries(inc).every(([k, x]) => !k.startsWith('incremental_storage') || (/check number/.test(x) && !/slow-down increment/.test(x))),
        'the incremental banks hold the check number, 318 and 310 the thousandths, 324 and 316 the inches', JSON.stringify(inc).slice(0, 300));
  await t.shot(page, 'part-info-laptop');
  // The part's state follows the machine: at the end every holding relay is open again.
  await page.click('#to-end');
  await page.waitForSelector('#run-state[data-finished="true"]');
  check(/every relay open/.test(await page.$eval('#part-info .live', (e) => e.textContent)), 'the chosen part\'s state follows the run');
  // By keyboard: a dial focused and Enter.
  await page.focus('#panel [data-scope="cross"] [data-name="absolute_counter_108"]');
  await page.keyboard.press('Enter');
  const dial = await page.$eval('#part-info', (e) => e.textContent);
  check(/108/.test(dial) && /stands at \d/.test(dial), 'a dial pressed with Enter tells its numeral and where it stands', dial.slice(0, 100));

  // ---- one relay event a press
  await page.click('#restart');
  for (let i = 0; i < 3; i++) {
    const before = await page.evaluate(() => window.parsonsViewer.ci);
    await page.click('#step-event');
    const after = await page.evaluate(() => {
      const v = window.parsonsViewer;
      const k = v.ci - 1;
      const sig = v.h.signals[v.a.change_id[k]];
      // The panel's part of that signal as drawn: a dial's position, a relay's or lamp's light.
      const part = document.querySelector(`#panel [data-signal="${v.a.change_id[k]}"]`);
      const drawn = !part ? null : part.classList.contains('dial') ? Number(part.dataset.value)
        : part.classList.contains('on') ? 'on' : 'off';
      const value = v.a.change_v[k];
      return { ci: v.ci, t: v.t, changeT: v.a.change_t[k], component: sig.component, value,
               shown: v.values[v.a.change_id[k]], note: document.getElementById('event-note').textContent,
               drawn, want: part && part.classList.contains('dial') ? value : value ? 'on' : 'off' };
    });
    check(after.ci === before + 1 && after.t === after.changeT && after.shown === after.value &&
          after.drawn === after.want &&
          after.note.includes(after.component) && after.note.endsWith(`→ ${after.value}`),
          `one relay event applies exactly the next change and the panel draws it (${i + 1})`,
          `${before} -> ${after.ci}: ${after.note}; drawn ${after.drawn}, recorded ${after.want}`);
  }

  // ---- the time slider: the middle of the record, forwards and then back from the end, stands
  // where the recorded changes say
  const mid = await page.evaluate(() => window.parsonsViewer.finish / 2);
  const atMid = async () => page.evaluate((m) => {
    const s = document.getElementById('scrub');
    s.value = String(m);
    s.dispatchEvent(new Event('input'));
    const v = window.parsonsViewer;
    // Independently of the viewer's state: each dial's last recorded value at or before m.
    // (The slider holds m as a range input's value, to double precision or about.)
    const last = new Map();
    for (let k = 0; k < v.a.change_t.length && v.a.change_t[k] <= v.t; k++) last.set(v.a.change_id[k], v.a.change_v[k]);
    const wrong = [];
    for (const d of document.querySelectorAll('#panel .dial')) {
      const id = Number(d.dataset.signal);
      const want = last.has(id) ? last.get(id) : v.h.signals[id].initial;
      if (Number(d.dataset.value) !== want) wrong.push(`${d.closest('[data-scope]').dataset.scope}.${d.dataset.name}`);
    }
    return { t: v.t, wrong, counters: document.querySelector('#positions tr[data-axis="table"] .counters').textContent };
  }, mid);
  const forward = await atMid();
  check(Math.abs(forward.t - mid) < 1e-6 && forward.wrong.length === 0, 'the slider seeks forwards to the recorded state', forward.wrong.join(' '));
  await page.click('#to-end');
  const back = await atMid();
  check(back.t === forward.t && back.wrong.length === 0 && back.counters === forward.counters,
        'the slider seeks back from the end to the same state', `${back.counters} against ${forward.counters}`);
  const follows = await page.evaluate(async () => {
    document.querySelector('.speeds [data-speed="100"]').click();
    document.getElementById('play').click();
    await new Promise((r) => setTimeout(r, 500));
    document.getElementById('pause').click();
    return [Number(document.getElementById('scrub').value), window.parsonsViewer.t];
  });
  check(Math.abs(follows[0] - follows[1]) < 1e-6 && follows[1] > mid, 'the slider follows playback', JSON.stringify(follows));
  // Played frame by frame at 10x (each frame's changes drawn, not the whole panel at once as
  // after a long jump), every part of the panel stands where the recorded changes say.
  const played = await page.evaluate(async () => {
    const ci0 = window.parsonsViewer.ci;
    document.querySelector('.speeds [data-speed="10"]').click();
    document.getElementById('play').click();
    await new Promise((r) => setTimeout(r, 400));
    document.getElementById('pause').click();
    const v = window.parsonsViewer;
    const last = new Map();
    for (let k = 0; k < v.a.change_t.length && v.a.change_t[k] <= v.t; k++) last.set(v.a.change_id[k], v.a.change_v[k]);
    const wrong = [];
    let parts = 0;
    for (const d of document.querySelectorAll('#panel [data-signal]')) {
      const id = Number(d.dataset.signal);
      const want = last.has(id) ? last.get(id) : v.h.signals[id].initial;
      const drawn = d.classList.contains('dial') ? Number(d.dataset.value) === want : d.classList.contains('on') === (want !== 0);
      parts++;
      if (!drawn) wrong.push(`${d.closest('[data-scope]').dataset.scope}.${d.dataset.name || d.closest('[data-bank]').dataset.bank}`);
    }
    return { wrong, parts, changed: v.ci - ci0 };
  });
  check(played.wrong.length === 0 && played.changed > 0,
        'played frame by frame, every part of the panel stands at the recorded state', JSON.stringify(played).slice(0, 300));

  // ---- speeds below 1x: machine time over a wall-clock interval
  const rate = async (speed, ms) => {
    await page.click('#restart');
    await page.click(`.speeds [data-speed="${speed}"]`);
    await page.click('#play');
    const t0 = Date.now();
    await sleep(ms);
    await page.click('#pause');
    const wall = (Date.now() - t0) / 1000;
    return (await page.evaluate(() => window.parsonsViewer.t)) / wall;
  };
  const r001 = await rate('0.01', 2000);
  const r01 = await rate('0.1', 1500);
  const r1 = await rate('1', 1000);
  console.log(`machine seconds a wall second: 0.01x ${r001.toFixed(4)}, 0.1x ${r01.toFixed(3)}, 1x ${r1.toFixed(2)}`);
  check(r001 > 0 && r001 <= 0.0125 && r01 > 0.05 && r01 <= 0.125 && r1 > 0.5 && r1 <= 1.25,
        'the speeds 0.01x and 0.1x play that much slower than 1x');

  // ---- the docs the page links to: the tour and the patent map, served beside it
  const docs = await page.evaluate(async () => Promise.all(['doc-tour', 'doc-patent-map'].map(async (id) => {
    const r = await fetch(document.getElementById(id).href);
    return [r.status, (await r.text()).split('\n')[0]];
  })));
  check(docs[0][0] === 200 && docs[0][1] === '# A tour: the sample deck, relay by relay' &&
        docs[1][0] === 200 && docs[1][1] === '# Patent numerals → code',
        'the page links to the tour and the patent map in the docs', JSON.stringify(docs));
  await page.close();

  // ---- the phone: the tour's caption is readable
  const phone = await t.open('phone');
  await phone.click('#tour-start');
  await phone.click('#tour-next');
  const box = await phone.$eval('#tour', (e) => { const r = e.getBoundingClientRect(); return [r.left, r.right]; });
  check(box[0] >= 0 && box[1] <= 390, 'the tour\'s caption fits the phone', JSON.stringify(box));
  await phone.$eval('#tour', (e) => e.scrollIntoView());
  await t.shot(phone, 'tour-phone');
  // A deck loaded while the tour is open is not run behind it: the tour's instant and record stay
  // until the visitor's next press.
  const atStop = await phone.evaluate(() => [window.parsonsViewer.t, window.parsonsViewer.finish]);
  await phone.$eval('#load-demo', (b) => b.click());
  await phone.waitForFunction(() => document.querySelectorAll('#cards figure').length > 50);
  await new Promise((r) => setTimeout(r, 300));
  const kept = await phone.evaluate(() => ({
    t: window.parsonsViewer.t, finish: window.parsonsViewer.finish,
    stop: document.getElementById('tour').dataset.stop, open: !document.getElementById('tour').hidden,
    ran: document.getElementById('run-state').dataset.ran,
  }));
  check(kept.open && kept.stop === '1' && kept.t === atStop[0] && kept.finish === atStop[1] && kept.ran === 'false',
        'a deck loaded while the tour is open leaves the tour on its record until the next press', JSON.stringify(kept));
  await phone.close();

  // ---- the --html replay carries the tour and the parts' stories
  const html = path.join(workDir, 'teach-replay.html');
  const sample = path.join(SOURCE, 'decks', 'samples', 'patent-example.csv');
  const h = parsons(['run', sample, '-q', '--html', html]);
  check(h.status === 0, 'run --html writes the replay', h.stderr);
  const replay = await t.browser.newPage();
  await replay.setViewport(t.SCREENS.laptop);
  watchPage(replay, t.problems);
  await replay.goto(`file://${html}`);
  await replay.click('#tour-start');
  await replay.click('#tour-next');
  const r = await replay.evaluate(() => ({ stop: document.getElementById('tour').dataset.numeral, t: window.parsonsViewer.t }));
  check(r.stop === '350' && r.t === seen[1].t, 'the replay\'s tour stops where the live page\'s does', JSON.stringify(r));
  await replay.close();
};
