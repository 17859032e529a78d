// The exhibit page's optional sound (docs/web.md), off by default: a click for every holding
// relay picked or dropped and for stepping relay 256 closing, a ratchet tick for every step of
// a stepping switch (the counters 104-110 and 310-316, speed switch 236, stepping shaft 280).
// It hears the changes the viewer applies from the recorded run (viewer.onChanges) and decides
// nothing about the machine; the sounds are synthesised here (Web Audio), nothing is fetched.
"use strict";

(() => {
  const button = document.getElementById("sound");
  if (!button) return;

  // Sounds scheduled this far ahead of the audio clock: the changes of one frame are already
  // in the past of the record when the viewer applies them, so they play one frame late, with
  // the spacing they had in the record.
  const LATENCY = 0.05;
  // At most this many sources a frame. Relay clicks are few; a counter stepping a thousand
  // times a second at 100x would be thousands: its ticks become one looped ratchet (a buzz).
  const MAX_SOURCES = 12;
  // The stepping switches, by patent numeral (docs/patent-map.md).
  const STEPPING = new Set(["104", "106", "108", "110", "310", "312", "314", "316", "236", "280"]);
  const RELAY = 1;
  const STEP_RELAY = 2; // stepping relay 256: a click when it closes only
  const RATCHET = 3;

  let ctx = null;
  let on = false;
  let clickBuffer = null;
  let tickBuffer = null;
  let kinds = null; // signal id -> RELAY, STEP_RELAY, RATCHET or 0, for the loaded record
  let kindsFor = null;
  let lastT = -1; // the machine time of the previous frame heard
  let lastWhen = 0; // the latest audio time scheduled: sounds never go back in time

  // A decaying burst of noise, coloured by a one-pole filter: the armature hitting its stop.
  function burst(seconds, decay, smooth, seed) {
    const rate = ctx.sampleRate;
    const b = ctx.createBuffer(1, Math.ceil(seconds * rate), rate);
    const d = b.getChannelData(0);
    let x = seed;
    let y = 0;
    for (let i = 0; i < d.length; i++) {
      x = (x * 1103515245 + 12345) >>> 0; // a fixed noise, the same click every time
      const noise = x / 2147483648 - 1;
      y += smooth * (noise - y);
      d[i] = y * Math.exp(-i / (decay * rate));
    }
    return b;
  }

  function makeBuffers() {
    clickBuffer = burst(0.012, 0.002, 0.6, 7); // short and bright
    clickBuffer.parsonsKind = "relay";
    // Duller and longer: the pawl on the ratchet. Silent after ~20 ms, and 50 ms long so that
    // a buzz can loop it at any spacing up to 50 ms (more than twelve ticks a frame are closer).
    tickBuffer = burst(0.05, 0.004, 0.25, 11);
    tickBuffer.parsonsKind = "ratchet";
  }

  function classify(h) {
    kinds = new Uint8Array(h.signals.length);
    h.signals.forEach((s, id) => {
      if (!s) return;
      if (/\.relay_\d+$/.test(s.name)) kinds[id] = RELAY; // the storage banks' holding relays
      else if (s.numeral === "256") kinds[id] = STEP_RELAY;
      else if (STEPPING.has(s.numeral)) kinds[id] = RATCHET;
    });
    kindsFor = h;
  }

  function play(buffer, when, gain, loopEvery, until) {
    const src = ctx.createBufferSource();
    src.buffer = buffer;
    const g = ctx.createGain();
    g.gain.value = gain;
    src.connect(g).connect(ctx.destination);
    if (loopEvery) {
      src.loop = true;
      src.loopEnd = loopEvery;
      src.start(when);
      src.stop(until);
    } else {
      src.start(when);
    }
  }

  // The viewer applied changes ci0..ci1-1, up to machine time t.
  function hear(viewer, ci0, ci1, t) {
    if (!on) return;
    if (kindsFor !== viewer.h) classify(viewer.h);
    const { change_t, change_id, change_v } = viewer.a;
    const speed = viewer.speed;
    // The frame began at the previous frame's machine time; after a pause or a restart, at
    // its first change.
    const t0 = lastT >= 0 && lastT <= change_t[ci0] && t - lastT <= 0.5 * speed ? lastT : change_t[ci0];
    lastT = t;
    const base = ctx.currentTime + LATENCY;
    const floor = lastWhen;
    const at = (i) => Math.max(floor, base + (change_t[i] - t0) / speed);
    const relays = [];
    const ticks = [];
    for (let i = ci0; i < ci1; i++) {
      const k = kinds[change_id[i]];
      if (k === RELAY || (k === STEP_RELAY && change_v[i] === 1)) relays.push(i);
      else if (k === RATCHET) ticks.push(i);
    }
    let budget = MAX_SOURCES;
    for (const i of relays.slice(0, budget)) {
      const when = at(i);
      play(clickBuffer, when, 0.5);
      lastWhen = Math.max(lastWhen, when);
    }
    budget -= Math.min(relays.length, budget);
    if (!ticks.length || !budget) return;
    if (ticks.length <= budget) {
      for (const i of ticks) {
        const when = at(i);
        play(tickBuffer, when, 0.3);
        lastWhen = Math.max(lastWhen, when);
      }
      return;
    }
    // Too many to tell apart: one ratchet looping at their mean rate, from the first to the last.
    const first = at(ticks[0]);
    const last = at(ticks[ticks.length - 1]);
    const every = Math.min(tickBuffer.duration, Math.max(0.002, (last - first) / (ticks.length - 1)));
    play(tickBuffer, first, 0.2, every, last + every);
    lastWhen = Math.max(lastWhen, last);
  }

  function show() {
    button.setAttribute("aria-pressed", String(on));
    button.textContent = on ? "Sound on" : "Sound off";
  }

  button.addEventListener("click", () => {
    const viewer = window.parsonsViewer;
    on = !on;
    if (on) {
      // Browsers let a page make sound only after a gesture: the context is made on this press.
      if (!ctx) {
        ctx = new (window.AudioContext || window.webkitAudioContext)();
        makeBuffers();
      }
      ctx.resume();
      lastT = -1;
      lastWhen = 0;
      if (viewer) viewer.onChanges = (ci0, ci1, t) => hear(viewer, ci0, ci1, t);
    } else {
      // Off: nothing more is scheduled, and what was is silenced at once.
      if (viewer) viewer.onChanges = null;
      ctx.suspend();
    }
    show();
  });
  show();
})();
