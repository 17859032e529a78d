// Signals you can watch travel (issue 52, item 3; docs/web.md): one axis's circuit drawn after
// the patent's Figs. 10-12 - the reader into the storage banks, the banks and the counters into
// comparers 122' and 122'', channel 257 and delay 258 to stepping relay 256, speed switch 236
// to the lead-screw motor, the screw's commutator feeding the counters, and at the stop contact
// 238 to balancing circuit 266 and master switch 204, and by channel 274 to stepping shaft 280.
// A part is lit while its recorded signal stands on; a wire lights as a change of the part it
// leads to arrives (played at the slow speeds, each change is seen travelling); the tour lights
// the path each stop tells. The parts' states are the record's: this draws, it decides nothing.
"use strict";

const ParsonsCircuit = (() => {
  const W = 660, H = 330;
  const FLASH_MS = 450; // how long a wire stays lit after a change came along it (wall time)

  // The parts: where, what, and the signal(s) that show them (AXIS. = the axis followed).
  const NODES = [
    { id: "reader", x: 20, y: 18, w: 110, label: "card reader 134", signals: ["cabinet.card_reader_134.reading"] },
    { id: "abs", x: 170, y: 18, w: 120, label: "storage 350–356", banks: "absolute_storage_" },
    { id: "inc", x: 170, y: 78, w: 120, label: "storage 318–324", banks: "incremental_storage_" },
    { id: "cmp1", x: 340, y: 18, w: 90, label: "comparer 122′", signals: ["AXIS.absolute_comparer_122a"] },
    { id: "cmp2", x: 340, y: 78, w: 90, label: "comparer 122″", signals: ["AXIS.incremental_comparer_122b"] },
    { id: "counters", x: 170, y: 148, w: 120, label: "counters 104–110", signals: ["AXIS.absolute_counter_110"], counts: true },
    { id: "inccount", x: 170, y: 208, w: 120, label: "counter 310–316", signals: ["AXIS.increment_counter_310"], counts: true },
    { id: "ch257", x: 470, y: 18, w: 80, label: "channel 257", signals: ["AXIS.channel_257"] },
    { id: "d258", x: 470, y: 78, w: 80, label: "delay 258", signals: ["AXIS.delay_device_258"] },
    { id: "r256", x: 575, y: 18, w: 75, label: "relay 256", signals: ["AXIS.stepping_relay_256"] },
    { id: "s236", x: 575, y: 108, w: 75, label: "speed sw. 236", signals: ["AXIS.speed_switch_236"], counts: true },
    { id: "motor", x: 575, y: 178, w: 75, label: "motor 38", signals: ["AXIS.motor_38"] },
    { id: "comm", x: 20, y: 178, w: 110, label: "commutator 96–102", signals: ["AXIS.commutator_102.contact_set_a"], counts: true },
    { id: "c238", x: 470, y: 178, w: 80, label: "contact 238", signals: ["AXIS.contact_238"] },
    { id: "b266", x: 340, y: 268, w: 90, label: "balancing 266", signals: ["cabinet.balancing_circuit_266"] },
    { id: "m204", x: 470, y: 268, w: 80, label: "master sw. 204", signals: ["cabinet.master_switch_204"] },
    { id: "ch274", x: 575, y: 268, w: 75, label: "ch. 274 → 280", signals: ["cabinet.channel_274", "cabinet.stepping_shaft_280"] },
    { id: "screw", x: 20, y: 268, w: 110, label: "lead screw", signals: ["AXIS.motor_38"] },
    { id: "z292", x: 340, y: 208, w: 100, label: "zeroizing 292", signals: ["cabinet.zeroizing_circuit_292"] },
  ];
  // The wires: from, to (a change of the part at `to` lights the wire that leads to it).
  const WIRES = [
    ["reader", "abs"], ["reader", "inc"], ["reader", "s236"],
    ["abs", "cmp1"], ["counters", "cmp1"], ["inc", "cmp2"], ["inccount", "cmp2"],
    ["comm", "counters"], ["comm", "inccount"],
    ["cmp1", "ch257"], ["ch257", "d258"], ["ch257", "r256"], ["d258", "r256"], ["r256", "s236"],
    ["s236", "motor"], ["motor", "screw"], ["screw", "comm"],
    ["s236", "c238"], ["cmp1", "c238"], ["cmp2", "c238"], ["c238", "b266"], ["b266", "m204"], ["c238", "ch274"],
    ["ch274", "z292"], ["z292", "abs"], ["z292", "inccount"], ["z292", "reader"],
  ];
  const BOX_H = 34;

  const svg = ParsonsCabinet.svg; // the page's SVG element maker (web/cabinet.js)

  class Circuit {
    constructor(box, viewer) {
      this.box = box;
      this.v = viewer;
      this.axis = null;
      this.flashUntil = new Map(); // wire key -> wall time its light goes out
    }

    // A new record (or another axis followed): the drawing and which signals feed which part.
    build(axis) {
      const h = this.v.h;
      this.box.textContent = "";
      this.axis = axis || this.axis || h.axes[0];
      if (!h.axes.includes(this.axis)) this.axis = h.axes[0];
      const ids = new Map(h.signals.map((s, i) => [s ? `${s.scope}.${s.name}` : "", i]));
      const doc = this.v.doc;
      const bar = doc.createElement("p");
      bar.className = "circuit-axis";
      bar.append("Follow the circuit of the ");
      const select = doc.createElement("select");
      select.id = "circuit-axis";
      select.setAttribute("aria-label", "the axis whose circuit is drawn");
      for (const a of h.axes) {
        const o = doc.createElement("option");
        o.value = a;
        o.textContent = a;
        select.appendChild(o);
      }
      select.value = this.axis;
      select.addEventListener("change", () => { this.build(select.value); this.renderAll(); });
      bar.append(select, " (its parts lit while on; a wire lights as a change reaches the part it leads to).");
      this.box.appendChild(bar);
      const root = svg("svg", { viewBox: `0 0 ${W} ${H}`, class: "circuit", role: "img",
                                "aria-label": `the circuit of the ${this.axis}, after Figs. 10-12: reader, storage, counters, comparers, stepping relay, speed switch, motor` }, this.box);
      this.root = root;
      root.dataset.axis = this.axis;
      this.nodeOf = new Map();  // signal id -> node ids it shows
      this.parts = new Map();   // node id -> {g, ids}
      const centre = (n) => [n.x + n.w / 2, n.y + BOX_H / 2];
      const byId = new Map(NODES.map((n) => [n.id, n]));
      this.wires = new Map();
      for (const [from, to] of WIRES) {
        const a = byId.get(from), b = byId.get(to);
        const [x1, y1] = centre(a), [x2, y2] = centre(b);
        const mx = (x1 + x2) / 2;
        const path = svg("path", { d: `M${x1} ${y1}C${mx} ${y1} ${mx} ${y2} ${x2} ${y2}`, class: "circuit-wire" }, root);
        path.dataset.wire = `${from}-${to}`;
        this.wires.set(`${from}-${to}`, { path, from, to });
      }
      for (const n of NODES) {
        const g = svg("g", { class: "circuit-part" }, root);
        g.dataset.part = n.id;
        svg("rect", { x: n.x, y: n.y, width: n.w, height: BOX_H, rx: 5 }, g);
        const t = svg("text", { x: n.x + n.w / 2, y: n.y + 14 }, g);
        t.textContent = n.label;
        const v = svg("text", { x: n.x + n.w / 2, y: n.y + 28, class: "circuit-value" }, g);
        let sigIds = (n.signals || []).map((s) => ids.get(s.replace("AXIS.", `${this.axis}.`))).filter((i) => i !== undefined);
        if (n.banks) {
          sigIds = h.signals.map((s, i) => (s && s.scope === this.axis && s.name.startsWith(n.banks) ? i : -1)).filter((i) => i >= 0);
        }
        for (const i of sigIds) {
          if (!this.nodeOf.has(i)) this.nodeOf.set(i, []);
          this.nodeOf.get(i).push(n.id);
        }
        g.dataset.signals = sigIds.join(" ");
        // Clicked, a part tells its story as the panel's part does (the panel's parts are the
        // buttons; this is a picture of them).
        g.addEventListener("click", () => {
          const part = sigIds.length ? this.v.doc.querySelector(`#panel [data-signal="${sigIds[0]}"]`) : null;
          if (part) part.click();
        });
        this.parts.set(n.id, { g, ids: sigIds, value: v, node: n });
      }
      this.lastT = -1;
    }

    // Each part at its value now.
    renderAll() {
      if (!this.root) return;
      for (const [, p] of this.parts) this.renderPart(p);
    }

    renderPart(p) {
      const values = this.v.values;
      const on = p.ids.some((i) => values[i] !== 0);
      p.g.classList.toggle("on", on);
      if (p.node.banks) {
        const closed = p.ids.filter((i) => values[i] !== 0).length;
        p.value.textContent = closed ? `${closed} relays held` : "";
      } else if (p.node.counts && p.ids.length) {
        p.value.textContent = String(values[p.ids[0]]);
      } else {
        p.value.textContent = p.ids.length ? (on ? "on" : "off") : "";
      }
    }

    // The signals that changed since the last frame: their parts redrawn, and while playing the
    // wires into those parts lit for a moment - a wire whose part at the far end is on, or
    // changed too (the zeroizing circuit's wires stay dark while the counters count).
    changed(ids) {
      if (!this.root) return;
      const now = performance.now();
      const parts = new Set();
      for (const i of ids) for (const n of this.nodeOf.get(i) || []) parts.add(n);
      for (const n of parts) this.renderPart(this.parts.get(n));
      if (this.v.playing) {
        for (const [key, w] of this.wires) {
          if (!parts.has(w.to)) continue;
          if (parts.has(w.from) || this.parts.get(w.from).g.classList.contains("on")) this.flashUntil.set(key, now + FLASH_MS);
        }
      }
      this.paintWires(now);
    }

    paintWires(now) {
      let lit = 0;
      for (const [key, w] of this.wires) {
        const on = (this.flashUntil.get(key) || 0) > now;
        w.path.classList.toggle("live", on);
        lit += on ? 1 : 0;
      }
      this.root.dataset.live = String(lit);
      if (lit && !this.timer) {
        this.timer = setTimeout(() => { this.timer = null; this.paintWires(performance.now()); }, FLASH_MS);
      }
    }

    // The tour: the path a stop tells, lit until the next stop (or the tour's end).
    lightPath(keys, axis) {
      if (axis && axis !== this.axis) { this.build(axis); this.renderAll(); }
      if (!this.root) return;
      for (const [key, w] of this.wires) w.path.classList.toggle("path", (keys || []).includes(key));
      this.root.dataset.path = (keys || []).join(" ");
    }
  }

  return { Circuit, WIRES };
})();
