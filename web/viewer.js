// The viewer of the exhibit page (web/index.html) and of `parsons run --html`: it plays a run
// that the C++ emulator recorded (outputs/replay/run_timeline.hpp) on machine time. It computes
// nothing of the machine: it applies the recorded signal changes in order and draws them, on
// the cabinet's panel (web/cabinet.js: relays as lamps, stepping switches as dials) and as the
// machine from above (the recorded positions as the cutter's path).
"use strict";

const ParsonsViewer = (() => {
  function b64bytes(text) {
    const bin = atob(text);
    const bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
    return bytes;
  }

  // The record `parsons run --html` packs (packed_record in outputs/replay/run_timeline.cpp):
  // ids as zigzag varints of their difference, values as varints, then the times and the
  // motion record's eight columns each as the bits XORed with the previous number's, written
  // as the low bytes that differ, their count a nibble. Read back bit for bit.
  function unpack(bytes, changes, records, stride) {
    let p = 0;
    const varint = () => {
      let n = 0, shift = 0, b;
      do { b = bytes[p++]; n += (b & 0x7f) * 2 ** shift; shift += 7; } while (b & 0x80);
      return n;
    };
    const change_id = new Uint32Array(changes);
    let id = 0;
    for (let i = 0; i < changes; i++) {
      const z = varint();
      id += z % 2 ? -(z + 1) / 2 : z / 2;
      change_id[i] = id;
    }
    const change_v = new Uint32Array(changes);
    for (let i = 0; i < changes; i++) change_v[i] = varint();
    // A column of `count` numbers into `out` (a Uint32Array over the Float64Array: two words a
    // number, the low first, as typed arrays are on every browser's machine), every `step`th
    // number from `first`.
    const column = (out, first, step, count) => {
      const nib = p;
      p += (count + 1) >> 1;
      let lo = 0, hi = 0;
      for (let i = 0; i < count; i++) {
        const n = (bytes[nib + (i >> 1)] >> ((i & 1) * 4)) & 15;
        if (n > 0) {
          let xlo = 0, xhi = 0;
          for (let k = 0; k < n; k++) {
            if (k < 4) xlo |= bytes[p++] << (8 * k);
            else xhi |= bytes[p++] << (8 * (k - 4));
          }
          lo = (lo ^ xlo) >>> 0;
          hi = (hi ^ xhi) >>> 0;
        }
        const at = (first + i * step) * 2;
        out[at] = lo;
        out[at + 1] = hi;
      }
    };
    const change_t = new Float64Array(changes);
    column(new Uint32Array(change_t.buffer), 0, 1, changes);
    const motion = new Float64Array(records * stride);
    const motionWords = new Uint32Array(motion.buffer);
    for (let c = 0; c < stride; c++) column(motionWords, c, stride, records);
    if (p !== bytes.length) throw new Error("the embedded record does not unpack whole");
    return { change_t, change_id, change_v, motion };
  }

  const { el, svg } = ParsonsCabinet;

  // A machine stop in a visitor's words, by the reason parsons reports (docs/stop-codes.md).
  const STOP_WORDS = {
    out_of_order_card: "a card came out of order, and the card-number check stopped the machine",
    check_mismatch: "an axis's two counters disagreed at its stop, and the balancing circuit opened the master switch",
    missed_impulse: "a counter missed an impulse from the lead screw",
    sequence_stall: "no axis that still had to move could start: the sequence stalled",
    bad_punch: "the reader found a badly punched card",
    soft_limit: "the card would have moved an axis past its soft limit",
    limit_switch: "an axis ran into its travel-limit switch",
    condition_not_met: "a condition card's condition was never met",
    condition_refused: "a condition card cannot run on this machine",
    tool_change_interlock: "the tool-change interlock held the machine",
    sync_timeout: "the press never came round to the angle the card waits for",
    sync_refused: "a press card cannot run on this machine",
    transfer_timeout: "the spindle's gear ratio never reached the control",
    tap_refused: "a tapping card cannot run on this machine",
    interrupted: "the operator stopped it",
  };

  class Viewer {
    constructor(doc) {
      this.doc = doc;
      this.speed = 1;
      this.playing = false;
      this.loaded = false;
      this.beforePlay = null; // live mode: runs the deck when it changed
      this.onFinished = null;
      const $ = (id) => doc.getElementById(id);
      this.$ = $;
      this.cabinet = new ParsonsCabinet.Cabinet(this);
      $("play").addEventListener("click", () => this.play());
      $("pause").addEventListener("click", () => this.pause());
      $("single-card").addEventListener("click", () => this.singleCard());
      $("restart").addEventListener("click", () => { if (this.ready()) { this.pause(); this.reset(); } });
      for (const b of doc.querySelectorAll(".speeds button")) {
        b.addEventListener("click", () => this.chooseSpeed(b.dataset.speed));
      }
      $("step-event").addEventListener("click", () => this.stepEvent());
      // The slider is the whole record; dragging it seeks, and playing moves it.
      const scrub = $("scrub");
      scrub.addEventListener("input", () => { if (this.ready()) this.seek(Number(scrub.value)); });
      this.enable(false);
      if (typeof ParsonsTour !== "undefined") this.tour = new ParsonsTour.Tour(this, doc);
      const millBox = doc.getElementById("mill");
      if (typeof ParsonsMill !== "undefined" && millBox) this.mill = new ParsonsMill.Mill(millBox, this);
      // The card in the reader (web/reader.js) and one axis's circuit (web/circuit.js).
      const readerBox = doc.getElementById("reader-view");
      if (typeof ParsonsReader !== "undefined" && readerBox) this.reader = new ParsonsReader.Reader(readerBox, this);
      const circuitBox = doc.getElementById("circuit-view");
      if (typeof ParsonsCircuit !== "undefined" && circuitBox) this.circuit = new ParsonsCircuit.Circuit(circuitBox, this);
    }

    // The value signal change k found: the change before it of the same signal, or the initial.
    valueBefore(k) {
      const { change_id, change_v } = this.a;
      const id = change_id[k];
      for (let j = k - 1; j >= 0; j--) if (change_id[j] === id) return change_v[j];
      return this.h.signals[id].initial;
    }

    enable(on) {
      for (const id of ["play", "pause", "single-card", "restart", "step-event", "scrub", "tour-start"]) {
        this.$(id).disabled = !on;
      }
    }

    ready() {
      // A deck run now is loaded without a first drawing: the caller moves on and draws.
      this.quietLoad = true;
      const ok = !this.beforePlay || this.beforePlay();
      this.quietLoad = false;
      return ok && this.loaded;
    }

    // header: cli/run_timeline.hpp's header(); arrays: its four arrays as typed arrays.
    load(header, arrays, report) {
      this.pause();
      this.h = header;
      this.a = arrays;
      this.report = report;
      this.finish = header.finish >= 0 ? header.finish
        : Math.max(arrays.change_t.length ? arrays.change_t[arrays.change_t.length - 1] : 0,
                   arrays.motion.length ? arrays.motion[arrays.motion.length - 8] : 0);
      this.cabinet.build();
      this.buildPositions();
      this.$("scrub").max = String(this.finish);
      this.prepareMachine();
      if (this.mill) this.mill.build();
      if (this.reader) this.reader.build();
      if (this.circuit) this.circuit.build();
      this.wholePath = null;
      const record = arrays;
      setTimeout(() => {
        if (this.a !== record) return;
        this.drawWholePath();
        if (!this.playing) this.drawMachine(); // the path ahead, faint, from the start on
      }, 0);
      this.showLegend();
      this.loaded = true;
      this.enable(true);
      this.reset(!this.quietLoad);
    }

    reset(draw = true) {
      const sigs = this.h.signals;
      this.values = new Uint32Array(sigs.length);
      sigs.forEach((s, i) => { if (s) this.values[i] = s.initial; });
      this.t = 0;
      this.ci = 0;
      // The record from before the run (where the axes start, RunTimeline::on_run_start) holds
      // from the start: the gauges and positions show it at once.
      const motion = this.a.motion;
      this.mi = 0;
      while (this.mi < motion.length / 8 && motion[this.mi * 8] <= 0) this.mi++;
      this.cardIndex = -1;
      this.drawnMotion = 0;
      this.finished = false;
      this.clearMachine();
      if (draw) this.renderAll();
      else this.allDirty = true;
    }

    chooseSpeed(speed) {
      for (const b of this.doc.querySelectorAll(".speeds button")) {
        b.setAttribute("aria-pressed", String(b.dataset.speed === speed));
      }
      if (speed === "end") {
        this.toEnd();
        return;
      }
      this.speed = Number(speed);
    }

    play(stopAt) {
      if (!this.ready()) return;
      if (this.finished) this.reset();
      this.stopAt = stopAt === undefined ? this.finish : stopAt;
      if (this.playing) return;
      this.playing = true;
      this.$("run-state").textContent = "running";
      let last = performance.now();
      const frame = (now) => {
        if (!this.playing) return;
        const dt = Math.min(0.25, (now - last) / 1000);
        last = now;
        const target = Math.min(this.stopAt, this.t + dt * this.speed);
        this.advanceTo(target);
        if (target >= this.stopAt) {
          this.playing = false;
          this.renderState();
          return;
        }
        requestAnimationFrame(frame);
      };
      requestAnimationFrame(frame);
    }

    pause() {
      this.playing = false;
      if (this.loaded) this.renderState();
    }

    // To the next card the reader senses (or the end).
    singleCard() {
      if (!this.ready()) return;
      if (this.finished) this.reset();
      const next = this.h.cards.find((c) => c.t > this.t + 1e-9);
      this.play(next ? next.t : this.finish);
    }

    // The end at once: the record's final values (cli/run_timeline.hpp), not every change.
    toEnd() {
      if (!this.ready()) return;
      this.playing = false;
      if (this.h.final_values && this.h.final_values.length === this.values.length) {
        this.values.set(this.h.final_values);
        this.ci = this.a.change_t.length;
        this.allDirty = true;
      }
      this.advanceTo(this.finish);
    }

    // Applies every recorded change up to machine time t, then draws.
    advanceTo(t) {
      const { change_t, change_id, change_v } = this.a;
      const dirty = this.dirty || (this.dirty = new Set());
      const values = this.values;
      let ci = this.ci;
      const n = change_t.length;
      // The parts changed are redrawn; after a long jump (more than 5000 changes) every part
      // once instead.
      const from = ci;
      while (ci < n && change_t[ci] <= t) {
        values[change_id[ci]] = change_v[ci];
        if (ci - from < 5000) dirty.add(change_id[ci]);
        ci++;
      }
      if (ci - from >= 5000) this.allDirty = true;
      // The sound (web/sound.js) hears the changes applied while playing, not a jump.
      if (this.onChanges && this.playing && ci > this.ci) this.onChanges(this.ci, ci, t);
      this.ci = ci;
      this.clockTo(t);
      this.render();
    }

    // The clock, the motion records and the card in the reader at machine time t.
    clockTo(t) {
      const motion = this.a.motion;
      let mi = this.mi;
      const records = motion.length / 8;
      while (mi < records && motion[mi * 8] <= t) mi++;
      this.mi = mi;
      const cards = this.h.cards;
      while (this.cardIndex + 1 < cards.length && cards[this.cardIndex + 1].t <= t) this.cardIndex++;
      this.t = t;
      this.finished = t >= this.finish;
    }

    // Machine time t at once, forwards or back: the record applied from the start up to t (the
    // same changes playing applies, so the same state), then drawn.
    seek(t) {
      if (!this.loaded) return;
      this.playing = false;
      const to = Math.min(Math.max(0, t), this.finish);
      if (to < this.t || this.finished) this.reset(false);
      this.advanceTo(to);
    }

    // One relay event: the next recorded change alone (of several at one instant, the next of
    // them), drawn, and said in words.
    stepEvent() {
      if (!this.ready()) return;
      this.playing = false;
      if (this.finished) this.reset(false);
      const { change_t, change_id, change_v } = this.a;
      const i = this.ci;
      const note = this.$("event-note");
      if (i >= change_t.length) {
        this.advanceTo(this.finish);
        note.textContent = "The record has no more events.";
        return;
      }
      const id = change_id[i];
      this.values[id] = change_v[i];
      (this.dirty || (this.dirty = new Set())).add(id);
      this.ci = i + 1;
      this.clockTo(change_t[i]);
      this.render();
      const sig = this.h.signals[id];
      note.textContent = `${change_t[i].toFixed(6)} s: ${sig.scope === "cabinet" ? "" : sig.scope + ", "}` +
        `${sig.component}${sig.numeral ? " " + sig.numeral : ""} → ${change_v[i]}`;
      note.dataset.change = String(i);
    }

    // ---- positions: the counters as the operator reads them, the recorded real positions

    buildPositions() {
      const table = this.$("positions");
      if (this.posKey !== this.h.axes.join(",") || this.cabinet.key !== this.posPanelKey) {
        this.posKey = this.h.axes.join(",");
        this.posPanelKey = this.cabinet.key;
      } else {
        return; // the same axes and signals: the rows and the counter ids stand
      }
      while (table.rows.length > 1) table.deleteRow(1);
      this.posCells = {};
      this.h.axes.forEach((axis) => {
        const tr = table.insertRow();
        tr.dataset.axis = axis;
        el("th", { text: axis }, tr);
        this.posCells[axis] = {
          counters: el("td", { class: "counters" }, tr),
          real: el("td", { class: "real" }, tr),
          angle: el("td", { class: "angle" }, tr),
        };
      });
      // The absolute counter dials of each axis, inches to thousandths (104, 106, 108, 110).
      this.counterIds = {};
      this.h.signals.forEach((s, id) => {
        const m = s && /^absolute_counter_(104|106|108|110)$/.exec(s.name);
        if (m) (this.counterIds[s.scope] || (this.counterIds[s.scope] = {}))[m[1]] = id;
      });
    }

    counterReading(axis) {
      const ids = this.counterIds[axis];
      if (!ids) return "";
      const v = (n) => this.values[ids[n]];
      return `${v(104)}.${v(106)}${v(108)}${v(110)}`;
    }

    // ---- the machine from above

    prepareMachine() {
      const m = this.a.motion;
      let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
      const grow = (x, y) => { x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y); };
      for (let i = 0; i < m.length; i += 8) grow(m[i + 1], m[i + 2]);
      const design = this.h.design && this.h.design.points ? this.h.design.points : [];
      for (const p of design) grow(p[0], p[1]);
      if (!isFinite(x0)) { x0 = 0; x1 = 1; y0 = 0; y1 = 1; }
      const r = this.h.design ? this.h.design.cutter_radius_in || 0 : 0;
      this.radius = r; // the cutter's, inches (0: no design, no band)
      const pad = Math.max(0.1, r * 1.5, 0.05 * Math.max(x1 - x0, y1 - y0));
      const canvas = this.$("from-above");
      const w = canvas.width, hgt = canvas.height;
      const scale = Math.min((w - 20) / (x1 - x0 + 2 * pad), (hgt - 20) / (y1 - y0 + 2 * pad));
      const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
      const pxX = (x) => w / 2 + (x - cx) * scale, pxY = (y) => hgt / 2 - (y - cy) * scale;
      this.toPx = (x, y) => [pxX(x), pxY(y)];
      this.scale = scale;
      // Every recorded point in pixels, once a record, and which of them the picture draws:
      // those a third of a pixel or more from the last drawn (a picture cannot show the others;
      // the point the tool stands at is always drawn as well).
      const n = m.length / 8;
      const px = new Float64Array(2 * n);
      const drawn = new Uint8Array(n);
      let lx = 0, ly = 0;
      for (let k = 0; k < n; k++) {
        const x = pxX(m[k * 8 + 1]), y = pxY(m[k * 8 + 2]);
        px[2 * k] = x;
        px[2 * k + 1] = y;
        if (k === 0 || Math.abs(x - lx) + Math.abs(y - ly) >= 0.33) {
          drawn[k] = 1;
          lx = x;
          ly = y;
        }
      }
      this.pathPx = px;
      this.pathDrawn = drawn;
      if (!this.layers || this.layers[0].width !== w || this.layers[0].height !== hgt) {
        this.layers = [0, 1].map(() => {
          const c = document.createElement("canvas");
          c.width = w; c.height = hgt;
          return c;
        });
      }
      this.buildGauges();
    }

    clearMachine() {
      for (const c of this.layers) c.getContext("2d").clearRect(0, 0, c.width, c.height);
      this.drawnMotion = 0;
    }

    buildGauges() {
      const box = this.$("side-gauges");
      box.textContent = "";
      const s = svg("svg", { viewBox: "0 0 300 90", width: 300, height: 90 }, box);
      // The vertical slide: a bar whose cutter head moves up and down.
      const vert = svg("g", { transform: "translate(10,5)" }, s);
      svg("rect", { x: 0, y: 0, width: 24, height: 80, class: "gauge-bg" }, vert);
      this.vertHead = svg("rect", { x: 2, y: 36, width: 20, height: 8, class: "gauge-head" }, vert);
      const tv = svg("text", { x: 30, y: 45, class: "gauge-text" }, vert);
      tv.textContent = "vertical";
      this.vertText = svg("text", { x: 30, y: 60, class: "gauge-text", "data-gauge": "vertical" }, vert);
      const plate = (x, name) => {
        const g = svg("g", { transform: `translate(${x},45)` }, s);
        svg("line", { x1: -40, y1: 0, x2: 40, y2: 0, class: "gauge-level" }, g);
        const bar = svg("line", { x1: -40, y1: 0, x2: 40, y2: 0, class: "gauge-plate" }, g);
        const t = svg("text", { x: -40, y: 38, class: "gauge-text" }, g);
        t.textContent = name;
        const v = svg("text", { x: -40, y: -28, class: "gauge-text", "data-gauge": name }, g);
        return { bar, v };
      };
      this.swivelGauge = plate(150, "swivel");
      this.tiltGauge = plate(250, "tilt (sine plate)");
      this.motionRange = { vmin: Infinity, vmax: -Infinity };
      const m = this.a.motion;
      for (let i = 0; i < m.length; i += 8) {
        this.motionRange.vmin = Math.min(this.motionRange.vmin, m[i + 3]);
        this.motionRange.vmax = Math.max(this.motionRange.vmax, m[i + 3]);
      }
    }

    // The path from recorded point `from` to `last` onto the two layers: the band the cutter
    // sweeps and its centre, through the points prepareMachine chose.
    strokePath(layers, from, last) {
      const [band, centre] = layers.map((c) => c.getContext("2d"));
      const r = this.radius;
      const px = this.pathPx, drawn = this.pathDrawn;
      const stroke = (g) => {
        g.beginPath();
        g.moveTo(px[2 * from], px[2 * from + 1]);
        for (let k = from + 1; k < last; k++) if (drawn[k]) g.lineTo(px[2 * k], px[2 * k + 1]);
        g.lineTo(px[2 * last], px[2 * last + 1]);
        g.stroke();
      };
      if (r > 0) {
        band.strokeStyle = "#b9d3e6";
        band.lineWidth = 2 * r * this.scale;
        band.lineCap = band.lineJoin = "round";
        stroke(band);
      }
      centre.strokeStyle = "#0b3d66";
      centre.lineWidth = 1.2;
      stroke(centre);
    }

    // The whole path, drawn once a record in a task of its own after the load (this.load): a
    // jump to the end (To the end, the slider at its end, a shared instant at the end) copies it
    // instead of stroking every point in the press. The same strokes as drawing it as it runs.
    drawWholePath() {
      const records = this.a.motion.length / 8;
      if (this.wholePath || records < 2) return;
      this.wholePath = this.layers.map((l) => {
        const c = this.doc.createElement("canvas");
        c.width = l.width;
        c.height = l.height;
        return c;
      });
      this.strokePath(this.wholePath, 0, records - 1);
    }

    drawMachine() {
      const m = this.a.motion;
      const r = this.radius;
      const from = Math.max(0, this.drawnMotion - 1);
      if (this.mi > from + 1) {
        if (from === 0 && this.mi === m.length / 8 && this.wholePath) {
          this.layers.forEach((l, i) => l.getContext("2d").drawImage(this.wholePath[i], 0, 0));
        } else this.strokePath(this.layers, from, this.mi - 1);
        this.drawnMotion = this.mi;
      }
      if (this.mill) this.mill.update(this.mi);
      const canvas = this.$("from-above");
      const g = canvas.getContext("2d");
      g.fillStyle = "#f6f3ea";
      g.fillRect(0, 0, canvas.width, canvas.height);
      if (this.wholePath) {
        // The whole path the run takes, faint: the box shows the job before Play, and the cut
        // grows over it.
        g.globalAlpha = 0.22;
        g.drawImage(this.wholePath[1], 0, 0);
        g.globalAlpha = 1;
      }
      g.drawImage(this.layers[0], 0, 0);
      const design = this.h.design && this.h.design.points ? this.h.design.points : [];
      if (design.length) {
        g.strokeStyle = "#c0392b";
        g.lineWidth = 1.5;
        g.beginPath();
        design.forEach((p, i) => { const [x, y] = this.toPx(p[0], p[1]); if (i) g.lineTo(x, y); else g.moveTo(x, y); });
        g.stroke();
      }
      g.drawImage(this.layers[1], 0, 0);
      if (this.mi > 0) {
        const k = (this.mi - 1) * 8;
        const [x, y] = this.toPx(m[k + 1], m[k + 2]);
        g.strokeStyle = "#e67e22";
        g.lineWidth = 2;
        g.beginPath();
        g.arc(x, y, Math.max(7, r * this.scale), 0, 2 * Math.PI);
        g.stroke();
        g.beginPath(); // the cutter centre, a cross to find it by
        g.moveTo(x - 11, y); g.lineTo(x + 11, y);
        g.moveTo(x, y - 11); g.lineTo(x, y + 11);
        g.stroke();
        // The gauges: vertical slide, swivel and tilt angles, as recorded.
        const { vmin, vmax } = this.motionRange;
        const span = vmax - vmin > 1e-9 ? vmax - vmin : 1;
        this.vertHead.setAttribute("y", (70 - ((m[k + 3] - vmin) / span) * 68).toFixed(1));
        this.vertText.textContent = `${m[k + 3].toFixed(3)} in`;
        const tilt = (gauge, deg) => {
          gauge.bar.setAttribute("transform", `rotate(${-deg})`);
          gauge.v.textContent = `${deg.toFixed(2)}°`;
        };
        tilt(this.swivelGauge, m[k + 6]);
        tilt(this.tiltGauge, m[k + 7]);
      } else {
        // No motion record at or before this instant (a record from before the run said where
        // the axes start): the gauges show nothing rather than an instant left behind.
        this.vertHead.setAttribute("y", "36");
        this.vertText.textContent = "";
        for (const gauge of [this.swivelGauge, this.tiltGauge]) {
          gauge.bar.setAttribute("transform", "rotate(0)");
          gauge.v.textContent = "";
        }
      }
    }

    // The picture's legend, in the page's own type under it (drawn into the canvas it was a
    // 6-pixel line once the canvas is scaled to the column).
    showLegend() {
      const legend = this.$("from-above-legend");
      if (!legend) return;
      legend.textContent = "";
      const item = (colour, words) => {
        const sw = this.doc.createElement("span");
        sw.className = "swatch";
        sw.style.background = colour;
        if (legend.childNodes.length) legend.append("; ");
        legend.append(sw, words);
      };
      const design = this.h.design && this.h.design.points && this.h.design.points.length;
      if (design) item("#c0392b", `the design, ${this.h.design.airfoil}`);
      item("rgba(11, 61, 102, 0.3)", "the path the deck takes");
      item("#0b3d66", design ? "the cut so far (blue band: the cutter's width)" : "the path so far");
      item("#e67e22", "the cutter now");
      legend.append(". Table → right, cross slide → up.");
    }

    // ---- drawing

    renderAll() {
      this.cabinet.renderAll();
      if (this.circuit) this.circuit.renderAll();
      if (this.reader) this.reader.update(this.t);
      this.dirty = new Set();
      this.allDirty = false;
      this.renderState();
    }

    render() {
      if (this.allDirty) {
        this.renderAll();
        return;
      }
      this.cabinet.render(this.dirty);
      if (this.circuit) this.circuit.changed(this.dirty);
      if (this.reader) this.reader.update(this.t);
      this.dirty.clear();
      this.renderState();
    }

    renderState() {
      const $ = this.$;
      const scrub = $("scrub");
      if (this.doc.activeElement !== scrub || this.playing) scrub.value = String(this.t);
      this.cabinet.renderPart();
      const mt = $("machine-time");
      mt.textContent = `${this.t.toFixed(3)} s of ${this.finish.toFixed(3)} s`;
      mt.dataset.seconds = String(this.t);
      const card = this.cardIndex >= 0 ? this.h.cards[this.cardIndex] : null;
      $("card-now").textContent = card ? `${card.index} (number ${String(card.number).padStart(4, "0")})` : "–";
      const state = $("run-state");
      const stop = this.h.stop;
      const stopMsg = $("stop-message");
      if (this.finished) {
        state.textContent = stop ? `machine stop: ${stop.reason}` : "completed";
        state.dataset.reason = stop ? stop.reason : "completed";
        state.dataset.finished = "true";
        stopMsg.hidden = !stop;
        if (stop) stopMsg.textContent = `parsons: machine stop: ${stop.reason}: ${stop.message}` + (stop.lamps && stop.lamps.length ? ` (lamps: ${stop.lamps.join(", ")})` : "");
        if (this.h.truncated) stopMsg.hidden = false, stopMsg.textContent += " The deck is longer than the page records: the playback ends early; the report is whole.";
      } else {
        state.textContent = this.playing ? "running" : this.t > 0 ? "paused" : "ready";
        state.dataset.reason = "";
        state.dataset.finished = "false";
        stopMsg.hidden = true;
      }
      const m = this.a.motion;
      const k = (this.mi - 1) * 8;
      this.h.axes.forEach((axis, i) => {
        const c = this.posCells[axis];
        c.counters.textContent = this.counterReading(axis);
        c.real.textContent = this.mi > 0 ? m[k + 1 + i].toFixed(5) : "";
        c.angle.textContent = this.mi > 0 && axis === "swivel" ? `${m[k + 6].toFixed(3)}°`
          : this.mi > 0 && axis === "tilt" ? `${m[k + 7].toFixed(3)}°` : "";
      });
      this.drawMachine();
      if (this.onState) this.onState(); // the page's top line (web/exhibit.js)
      // The finished view is whole: the cabinet, the positions and the picture drawn.
      if (this.finished && this.onFinished) this.onFinished();
    }

    // What the machine is doing at the instant shown, in a visitor's words: [state, sentence]
    // for the page's top line. The exact words of a stop stay under the controls
    // (#stop-message), as parsons run prints them.
    statusWords() {
      if (!this.loaded) return ["ready", "The machine is ready: the deck is in the keypunch. Press Play."];
      const tour = this.tour && this.tour.active && !this.playing ? this.tour : null;
      if (tour) {
        const r = tour.route;
        return ["tour", `Tour of card ${r.card}, stop ${tour.n + 1} of ${r.stops.length}: ` +
          `${r.stops[tour.n].title}. The machine is held at ${this.t.toFixed(3)} s; Next goes on.`];
      }
      const card = this.cardIndex >= 0 ? this.h.cards[this.cardIndex] : null;
      const reading = card ? `card ${card.index} in the reader` : "the reader feeding the first card";
      if (this.finished) {
        const stop = this.h.stop;
        if (stop) {
          const what = STOP_WORDS[stop.reason] || stop.reason.replace(/_/g, " ");
          return ["stopped", `The machine stopped itself on card ${stop.card}` +
            `${stop.axis ? ` (${stop.axis})` : ""}: ${what}. Its lamps and the exact words are ` +
            "under the controls."];
        }
        const n = this.h.cards.length;
        return ["completed", `The deck ran to the end: ${n} card${n === 1 ? "" : "s"} in ` +
          `${this.finish.toFixed(1)} s of machine time. From the start runs it again.`];
      }
      if (this.playing) return ["running", `Running: ${reading}, ${this.t.toFixed(1)} s of machine time.`];
      if (this.t > 0) return ["paused", `Paused at ${this.t.toFixed(3)} s, ${reading}. Play goes on.`];
      return ["ready", "The machine is ready: the deck is in the reader. Press Play."];
    }
  }

  // `parsons run --html`: the run embedded in the page.
  function replayFromPage(doc) {
    const timeline = JSON.parse(doc.getElementById("parsons-timeline").textContent);
    const run = JSON.parse(doc.getElementById("parsons-run").textContent);
    const t0 = performance.now();
    const arrays = unpack(b64bytes(timeline.arrays.packed), timeline.changes,
                          timeline.motion_records, 8);
    window.parsonsUnpackMs = performance.now() - t0; // printed by the browser check
    const viewer = new Viewer(doc);
    viewer.load(timeline, arrays, run.report);
    window.parsonsViewer = viewer;
    return viewer;
  }

  return { Viewer, replayFromPage, unpack };
})();
