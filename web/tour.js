// The guided tour of one card (docs/web.md): one real card of the loaded run followed through
// the cabinet, stop by stop, from the reader's brushes to zeroizing. Each stop is an instant the
// C++ recorded (the first change of a part's signal after the stop before), so the tour shows
// the machine as it ran, never a story told beside it: the viewer is moved to that instant, the
// part is lit on the panel, and the caption says in plain words what happened, with the
// patent's passage and figure (web/parts.js).
"use strict";

const ParsonsTour = (() => {
  // Each stop: the part it is about (its numeral, for the passage), where to look for it (the
  // axis the tour follows, or the shared cabinet), the signals that show it on the panel, the
  // recorded change that marks it, and what to say.
  const STOPS = [
    {
      numeral: "134", scope: "cabinet", names: ["card_reader_134.reading", "card_reader_134.card"],
      when: { name: "card_reader_134.reading", value: 1 },
      title: "The card reader and its brushes",
      path: ["reader-abs", "reader-inc", "reader-s236"], // the wires it lights in the circuit (web/circuit.js)
      words: (c) => `Card ${c.card} goes into reader 134. Brushes press on the card; where a hole is punched a brush touches the roller beneath and closes a circuit. That is how the machine reads a number: one circuit for each hole.`,
    },
    {
      numeral: "350", scope: "axis", banks: ["absolute_storage_350", "absolute_storage_352", "absolute_storage_354", "absolute_storage_356"],
      when: { bank: "absolute_storage_35", value: 1 },
      title: "The storage banks remember the numbers",
      path: ["reader-abs", "abs-cmp1"], // the wires it lights in the circuit (web/circuit.js)
      words: (c) => `The holes close holding relays in banks 350–356, one bank for each digit (inches, tenths, hundredths, thousandths). For the ${c.axis} they hold where to slow down and where to stop. A relay stays closed by its own holding coil after the card has moved on.`,
    },
    {
      numeral: "318", scope: "axis", banks: ["incremental_storage_318", "incremental_storage_320", "incremental_storage_322", "incremental_storage_324"],
      when: { bank: "incremental_storage_3", value: 1 },
      title: "The check number is stored too",
      path: ["reader-inc", "inc-cmp2"], // the wires it lights in the circuit (web/circuit.js)
      words: (c) => `Banks 318–324 hold the card's check number for the ${c.axis}: how far this move goes. A second counter will count the move from zero, so that at the stop two independent counts can be compared.`,
    },
    {
      numeral: "236", scope: "axis", names: ["speed_switch_236", "contact_238"],
      when: { name: "speed_switch_236", from: 0 },
      title: "The speed switch is set",
      path: ["reader-s236", "s236-motor"], // the wires it lights in the circuit (web/circuit.js)
      words: (c) => `A second bank of brushes reads the speed columns. Each punched speed sends one impulse to speed switch 236 of the ${c.axis}, which leaves "off" and steps to the start speed. When the sequence lets this axis go, its motor runs at that speed.`,
    },
    {
      numeral: "256", scope: "axis", names: ["absolute_comparer_122a", "channel_257", "stepping_relay_256", "speed_switch_236"],
      when: { name: "stepping_relay_256", value: 1 },
      title: "A comparer slows the axis down",
      path: ["s236-motor", "motor-screw", "screw-comm", "comm-counters", "counters-cmp1", "abs-cmp1", "cmp1-ch257", "ch257-r256", "r256-s236"], // the wires it lights in the circuit (web/circuit.js)
      words: (c) => `The lead screw turns; every 0.001 inch a commutator sends an impulse and the counters step on. When the counters read the slow-down number held in the banks, comparer 122′ conducts and sends an impulse through channel 257 to stepping relay 256, which steps speed switch 236 one speed slower.`,
    },
    {
      numeral: "258", scope: "axis", names: ["delay_device_258", "stepping_relay_256"],
      when: { name: "delay_device_258", value: 1 },
      title: "The delay keeps it to one step",
      path: ["cmp1-ch257", "ch257-d258", "d258-r256", "r256-s236"], // the wires it lights in the circuit (web/circuit.js)
      words: () => `Delay device 258 opens the channel to the stepping relay for a moment after each step, so that one closing of the comparer moves the speed switch only one position.`,
    },
    {
      numeral: "270", scope: "axis", names: ["speed_switch_236", "contact_238", "lamp_270", "lamp_272", "incremental_comparer_122b"],
      when: { name: "speed_switch_236", value: 0 },
      title: "The stop, and the check",
      path: ["comm-counters", "comm-inccount", "counters-cmp1", "inccount-cmp2", "cmp1-c238", "cmp2-c238", "s236-c238", "c238-b266", "b266-m204"], // the wires it lights in the circuit (web/circuit.js)
      words: (c) => `At the stop number the last impulse steps switch 236 to "off": the ${c.axis}'s motor stops. Now both comparers must agree: lamp 270 shows the position equals the stop, lamp 272 that the counted move equals the check number. If they disagreed, indicator 268 would light and the machine would stop.`,
    },
    {
      numeral: "280", scope: "cabinet", names: ["stepping_shaft_280", "motor_278", "channel_274", "unit_284"],
      when: { name: "stepping_shaft_280" },
      title: "The stepping shaft starts the next axes",
      path: ["s236-c238", "c238-ch274"], // the wires it lights in the circuit (web/circuit.js)
      words: () => `Each axis that stops sends an impulse to motor 278, which turns stepping shaft 280 one step. The shaft's rotary members close the sequence contacts of the next step, so the axes punched for it start: this is how the card says which axes move first.`,
    },
    {
      numeral: "292", scope: "cabinet", names: ["zeroizing_contact_290", "zeroizing_circuit_292", "channel_294", "channel_298", "channel_300", "channel_302", "channel_304"],
      when: { name: "zeroizing_circuit_292", value: 1 },
      title: "Zeroizing: ready for the next card",
      path: ["ch274-z292", "z292-abs", "z292-inccount", "z292-reader"], // the wires it lights in the circuit (web/circuit.js)
      words: () => `When the shaft has gone all the way round it closes contact 290: zeroizing circuit 292 drops every holding relay (channel 294), homes the check counters (298), opens the sequence contacts (300), resets the shaft's circuit (302) and feeds the next card (304).`,
    },
  ];

  class Tour {
    constructor(viewer, doc) {
      this.v = viewer;
      this.doc = doc;
      this.box = doc.getElementById("tour");
      doc.getElementById("tour-start").addEventListener("click", () => this.start());
    }

    // The recorded instants of the stops for the card in the reader now (card 1 before the run).
    plan() {
      const v = this.v;
      const cards = v.h.cards;
      const at = v.finished || v.cardIndex < 0 ? 0 : v.cardIndex;
      const card = cards[at];
      const end = at + 1 < cards.length ? cards[at + 1].t : v.finish;
      const { change_t, change_id, change_v } = v.a;
      const sigs = v.h.signals;
      // The card's cycle begins where the reader starts on it: the reader's last "reading" at or
      // before the card's time.
      let i = 0;
      while (i < change_t.length && change_t[i] <= card.t) i++;
      for (let k = i - 1; k >= 0; k--) {
        const s = sigs[change_id[k]];
        if (s.scope === "cabinet" && s.name === "card_reader_134.reading" && change_v[k] === 1) {
          i = k;
          break;
        }
      }
      // The axis followed: the first whose storage the card fills.
      let axis = null;
      for (let k = i; k < change_t.length && change_t[k] <= end && !axis; k++) {
        const s = sigs[change_id[k]];
        if (/^absolute_storage_35\d\.relay_/.test(s.name) && change_v[k] === 1) axis = s.scope;
      }
      axis = axis || v.h.axes[0];
      const stops = [];
      for (const stop of STOPS) {
        const scope = stop.scope === "axis" ? axis : "cabinet";
        let found = -1;
        for (let k = i; k < change_t.length && change_t[k] <= end; k++) {
          const s = sigs[change_id[k]];
          if (s.scope !== scope) continue;
          const w = stop.when;
          const named = w.bank ? s.name.startsWith(w.bank) : s.name === w.name;
          if (!named) continue;
          if (w.value !== undefined && change_v[k] !== w.value) continue;
          if (w.from !== undefined && (v.valueBefore(k) !== w.from || change_v[k] === w.from)) continue;
          found = k;
          break;
        }
        // A stop the card does not make (an axis with no slow-down, say) is left out.
        if (found < 0) continue;
        stops.push({ ...stop, scope, change: found, t: change_t[found] });
        i = found + 1;
      }
      return { card: card.index, number: card.number, axis, stops };
    }

    start() {
      if (!this.v.ready()) return;
      this.route = this.plan();
      this.active = true;
      this.doc.body.classList.add("touring");
      this.show(0);
    }

    show(n) {
      const r = this.route;
      if (n < 0 || n >= r.stops.length) return;
      this.n = n;
      const stop = r.stops[n];
      this.v.seek(stop.t);
      const box = this.box;
      box.textContent = "";
      const h = this.doc.createElement("h3");
      h.textContent = `Tour of card ${r.card} · stop ${n + 1} of ${r.stops.length}: ${stop.title}`;
      const p = this.doc.createElement("p");
      p.textContent = stop.words({ card: r.card, axis: r.axis });
      const [fig, passage] = ParsonsParts.passage(stop.numeral);
      const q = this.doc.createElement("blockquote");
      q.textContent = `“${passage}”`;
      const f = this.doc.createElement("p");
      f.className = "fig";
      f.textContent = `US 2,820,187, ${fig} · at ${stop.t.toFixed(6)} s of machine time`;
      const nav = this.doc.createElement("div");
      nav.className = "tour-nav";
      const button = (text, id, fn, disabled) => {
        const b = this.doc.createElement("button");
        b.type = "button";
        b.textContent = text;
        b.id = id;
        b.disabled = disabled;
        b.addEventListener("click", fn);
        nav.appendChild(b);
        return b;
      };
      button("◀ Back", "tour-back", () => this.show(this.n - 1), n === 0);
      const next = button("Next ▶", "tour-next", () => this.show(this.n + 1), n === r.stops.length - 1);
      button("End the tour", "tour-end", () => this.end(), false);
      box.append(h, p, q, f, nav);
      box.dataset.stop = String(n);
      box.dataset.numeral = stop.numeral;
      box.hidden = false;
      if (this.v.circuit) this.v.circuit.lightPath(stop.path, r.axis);
      this.highlight(stop); // after the caption is shown: on a phone it is a sheet to keep clear of
      (next.disabled ? this.doc.getElementById("tour-end") : next).focus({ preventScroll: true });
    }

    highlight(stop) {
      for (const old of this.doc.querySelectorAll("#panel .tour-here")) old.classList.remove("tour-here");
      const col = this.doc.querySelector(`#panel [data-scope="${stop.scope}"]`);
      if (!col) return;
      const parts = [
        ...(stop.names || []).map((n) => col.querySelector(`[data-name="${n}"]`)),
        ...(stop.banks || []).map((b) => col.querySelector(`[data-bank="${b}"]`)),
      ].filter(Boolean);
      for (const p of parts) p.classList.add("tour-here");
      for (const old of this.doc.querySelectorAll("#panel [data-tour-main]")) delete old.dataset.tourMain;
      if (!parts.length) return;
      parts[0].dataset.tourMain = "true"; // the part the stop is about
      const sheet = this.doc.defaultView.getComputedStyle(this.box).position === "fixed";
      if (!sheet) {
        parts[0].scrollIntoView({ block: "nearest", inline: "nearest" });
        return;
      }
      // A phone: the caption is a sheet over the screen's foot (web/exhibit.css); the parts lit
      // go to the top of the screen above it.
      const win = this.doc.defaultView;
      const rects = parts.map((p) => p.getBoundingClientRect());
      const top = Math.min(...rects.map((r) => r.top));
      const height = Math.max(...rects.map((r) => r.bottom)) - top;
      const room = this.box.getBoundingClientRect().top - height - 8; // lowest top that clears it
      if (room >= 8) {
        win.scrollBy(0, top - Math.min(win.innerHeight * 0.15, room));
        return;
      }
      // The parts lit are spread further than the screen above the caption holds: the part the
      // stop is about goes there.
      win.scrollBy(0, parts[0].getBoundingClientRect().top - win.innerHeight * 0.15);
    }

    end() {
      for (const old of this.doc.querySelectorAll("#panel .tour-here")) old.classList.remove("tour-here");
      if (this.v.circuit) this.v.circuit.lightPath([]);
      this.box.hidden = true;
      this.active = false;
      this.doc.body.classList.remove("touring");
      if (this.v.onState) this.v.onState();
      if (this.onEnd) this.onEnd(); // the live page offers a next step (web/guide.js)
      else this.doc.getElementById("tour-start").focus();
    }
  }

  return { Tour, STOPS };
})();
