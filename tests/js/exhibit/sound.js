// The exhibit page's optional sound (web/sound.js, docs/web.md), run by tests/js/browser_test.js:
// off by default, no AudioContext before the visitor asks; pressed, a click for every holding
// relay picked or dropped and for relay 256 closing, a ratchet tick for every step of a stepping
// switch, each at the audio time its change has in the record; at most 12 sources a frame, more
// ticks as one looped ratchet; no sound for a jump to the end; pressed again, nothing more.
// The page's AudioContext and AudioBufferSourceNode.start are wrapped before the page loads,
// so the check sees every context made and every sound scheduled.
'use strict';

const path = require('path');
const { watchPage } = require('../web_support');

const CAP = 12; // web/sound.js MAX_SOURCES
const STEPPING = ['104', '106', '108', '110', '310', '312', '314', '316', '236', '280'];

module.exports = async function sound(t) {
  const { browser, server, SCREENS, problems, check } = t;
  const page = await browser.newPage();
  await page.setViewport(SCREENS.laptop);
  watchPage(page, problems);
  await page.evaluateOnNewDocument(() => {
    const audio = { made: 0, starts: [], calls: null, ctx: null };
    window.__audio = audio;
    const Native = window.AudioContext;
    window.AudioContext = class extends Native {
      constructor(...args) { super(...args); audio.made++; audio.ctx = this; }
    };
    const start = AudioBufferSourceNode.prototype.start;
    AudioBufferSourceNode.prototype.start = function (when, ...rest) {
      audio.starts.push({ when, kind: this.buffer && this.buffer.parsonsKind, loop: this.loop,
                          loopEnd: this.loopEnd, call: audio.calls ? audio.calls.length - 1 : -1 });
      return start.call(this, when, ...rest);
    };
  });
  await page.goto(`${server.url}/index.html`);
  await page.waitForSelector('body[data-settled="true"]', { timeout: 30000 });
  const button = () => page.$eval('#sound', (b) => [b.getAttribute('aria-pressed'), b.textContent]);

  // ---- off by default: no context, the button says so
  let made = await page.evaluate(() => window.__audio.made);
  let state = await button();
  check(made === 0 && state[0] === 'false' && state[1] === 'Sound off',
        'the sound is off by default and no AudioContext is made on load', `${made} contexts, ${state}`);

  // ---- pressed: on, one context; every change the viewer applies while playing is recorded
  await page.click('#sound');
  made = await page.evaluate(() => window.__audio.made);
  state = await button();
  check(made === 1 && state[0] === 'true' && state[1] === 'Sound on',
        'pressing Sound turns it on, and makes the AudioContext then', `${made} contexts, ${state}`);
  await page.evaluate(() => {
    const v = window.parsonsViewer;
    const heard = v.onChanges;
    window.__audio.calls = [];
    v.onChanges = (ci0, ci1, t) => {
      window.__audio.calls.push({ ci0, ci1, t, speed: v.speed, now: window.__audio.ctx.currentTime });
      heard(ci0, ci1, t);
    };
  });
  const playFor = async (speed, machineSeconds) => {
    await page.click(`.speeds [data-speed="${speed}"]`);
    await page.click('#play');
    await page.waitForFunction((s) => window.parsonsViewer.t >= s, { timeout: 60000 }, machineSeconds);
    await page.click('#pause');
  };
  // 1x over the first card's reading (44 holding relays picked at 0.16 s, speed switches set,
  // the first counter steps), then 100x: thousands of counter steps a second.
  await playFor('1', 1.5);
  await t.shot(page, 'sound-on-laptop');
  const at1 = await page.evaluate(() => window.__audio.calls.length);
  await playFor('100', 300);

  // What the record says each frame should have sounded, against what was scheduled.
  const r = await page.evaluate((CAP, STEPPING) => {
    const v = window.parsonsViewer;
    const { change_t, change_id, change_v } = v.a;
    const kind = v.h.signals.map((s) => !s ? '' : /\.relay_\d+$/.test(s.name) ? 'relay'
      : s.numeral === '256' ? '256' : STEPPING.includes(s.numeral) ? 'ratchet' : '');
    const { calls, starts } = window.__audio;
    const out = { calls: calls.length, relays: 0, ticks: 0, buzzes: 0, capped: 0, bad: [], late: 0,
                  maxAhead: 0, steppingSeen: new Set() };
    const seq = [];
    out.closings256 = 0;
    calls.forEach((c, n) => {
      const relays = [];
      const ticks = [];
      for (let i = c.ci0; i < c.ci1; i++) {
        const k = kind[change_id[i]];
        if (k === 'relay' || (k === '256' && change_v[i] === 1)) {
          relays.push(i);
          if (k === '256' && relays.length <= CAP) out.closings256++;
        }
        else if (k === 'ratchet') { ticks.push(i); out.steppingSeen.add(v.h.signals[change_id[i]].numeral); }
      }
      const got = starts.filter((s) => s.call === n);
      const wantRelays = relays.slice(0, CAP);
      const budget = CAP - wantRelays.length;
      let want = wantRelays.map((i) => ({ i, kind: 'relay', loop: false }));
      if (ticks.length && budget) {
        want = want.concat(ticks.length <= budget ? ticks.map((i) => ({ i, kind: 'ratchet', loop: false }))
                                                  : [{ i: ticks[0], kind: 'ratchet', loop: true }]);
      }
      if (relays.length > CAP) out.capped++;
      const same = got.length === want.length && got.every((s, j) => s.kind === want[j].kind && s.loop === want[j].loop);
      if (!same) { out.bad.push({ n, got: got.map((s) => s.kind + (s.loop ? '~' : '')), want: want.map((w) => w.kind + (w.loop ? '~' : '')) }); return; }
      // In time with the record: the audio times keep the record's spacing at this speed (one
      // offset for the frame), except that none goes back before the previous frame's last:
      // those wait for it, at the frame's earliest time.
      if (!got.length) return;
      const offset = Math.min(...got.map((s, j) => s.when - change_t[want[j].i] / c.speed));
      const first = Math.min(...got.map((s) => s.when));
      got.forEach((s, j) => {
        seq.push({ ci: want[j].i, when: s.when });
        const recorded = change_t[want[j].i] / c.speed + offset;
        if (Math.abs(s.when - recorded) > 1e-6 && !(s.when === first && s.when > recorded)) {
          out.bad.push({ n, j, when: s.when, recorded });
        }
        if (s.when < c.now) out.late++;
        out.maxAhead = Math.max(out.maxAhead, s.when - c.now);
      });
      out.relays += got.filter((s) => s.kind === 'relay').length;
      out.ticks += got.filter((s) => s.kind === 'ratchet' && !s.loop).length;
      out.buzzes += got.filter((s) => s.loop).length;
    });
    // In the record's order: by change, the audio times never go back.
    seq.sort((a, b) => a.ci - b.ci);
    out.ordered = seq.every((s, j) => j === 0 || s.when >= seq[j - 1].when);
    out.starts = starts.length;
    out.steppingSeen = [...out.steppingSeen].sort().join(' ');
    return out;
  }, CAP, STEPPING);
  console.log(`sound: ${r.calls} frames heard (${at1} at 1x), ${r.starts} sources: ${r.relays} relay clicks, ` +
              `${r.ticks} ratchet ticks, ${r.buzzes} looped ratchets; ${r.capped} frames over the cap; ` +
              `at most ${(r.maxAhead * 1000).toFixed(0)} ms ahead of the audio clock; switches heard: ${r.steppingSeen}`);
  check(r.bad.length === 0, 'each frame schedules the clicks and ticks of the relay and stepping-switch changes it applied, ' +
        'at most 12, in the record\'s time', JSON.stringify(r.bad.slice(0, 5)));
  check(r.relays > r.closings256 && r.closings256 > 0 && r.capped > 0,
        'holding relays and stepping relay 256 (closing) click, at most 12 a frame',
        `${r.relays} clicks, ${r.closings256} of relay 256, ${r.capped} capped frames`);
  check(r.ticks > 0 && r.buzzes > 0, 'stepping switches tick, one by one when few and as a looped ratchet when many',
        `${r.ticks} ticks, ${r.buzzes} loops`);
  check(r.ordered && r.late === 0 && r.maxAhead < 0.5, 'the sounds are scheduled in the record\'s order, ahead of the audio clock and less than 0.5 s ahead',
        `ordered ${r.ordered}, ${r.late} late, ${r.maxAhead.toFixed(3)} s ahead`);

  // ---- a jump to the end makes no sound
  let before = await page.evaluate(() => window.__audio.starts.length);
  await page.click('#to-end');
  await page.waitForSelector('#run-state[data-finished="true"]');
  let after = await page.evaluate(() => window.__audio.starts.length);
  check(after === before, '"To the end" schedules no sound', `${after - before} sources`);

  // ---- pressed again: off, and playing schedules nothing more
  await page.click('#restart');
  await page.click('#sound');
  state = await button();
  before = await page.evaluate(() => window.__audio.starts.length);
  await playFor('1', 1.5);
  after = await page.evaluate(() => window.__audio.starts.length);
  check(state[0] === 'false' && state[1] === 'Sound off' && after === before,
        'pressing Sound again turns it off and nothing more is scheduled', `${state}, ${after - before} sources`);
  // On once more: the same context serves.
  await page.click('#sound');
  made = await page.evaluate(() => window.__audio.made);
  check(made === 1, 'the AudioContext is made once', `${made} contexts`);
  await page.click('#sound');

  await page.close();

  // ---- the --html replay carries the sound too: pressed and played, it schedules sounds
  const html = path.join(t.workDir, 'sound-replay.html');
  const written = t.parsons(['run', path.join(t.SOURCE, 'decks', 'samples', 'patent-example.csv'), '-q', '--html', html]);
  check(written.status === 0, 'run --html writes the replay', written.stderr);
  const replay = await browser.newPage();
  await replay.setViewport(SCREENS.laptop);
  watchPage(replay, problems);
  await replay.evaluateOnNewDocument(() => {
    const audio = { made: 0, starts: 0 };
    window.__audio = audio;
    const Native = window.AudioContext;
    window.AudioContext = class extends Native { constructor(...a) { super(...a); audio.made++; } };
    const start = AudioBufferSourceNode.prototype.start;
    AudioBufferSourceNode.prototype.start = function (...a) { audio.starts++; return start.apply(this, a); };
  });
  await replay.goto(`file://${html}`);
  const shown = await replay.$eval('#sound', (b) => getComputedStyle(b).display !== 'none');
  await replay.click('#sound');
  await replay.click('.speeds [data-speed="100"]');
  await replay.click('#play');
  await new Promise((res) => setTimeout(res, 800));
  await replay.click('#pause');
  const heard = await replay.evaluate(() => window.__audio);
  check(shown && heard.made === 1 && heard.starts > 0, 'the --html replay plays the sound too', JSON.stringify(heard));
  await replay.close();
};
