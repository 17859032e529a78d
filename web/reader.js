// The card, read (issue 52, item 2; docs/web.md): the card in reader 134 as the record has it,
// hole for hole, the first bank of brushes passing over it row by row, then the second. Where
// the first bank finds a hole its brush lights, and so does the relay, switch or contact that
// hole picks on the panel: the brushes' wiring is the machine's (relaylogic::brush_wiring,
// carried in the record), the instants are the record's (the card entering the reader, the
// first bank's sensing, the speed switches stepped by the second). Nothing here decides what a
// hole means.
"use strict";

const ParsonsReader = (() => {
  const ROWS = [12, 11, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9]; // top edge down (cardreader/card.hpp)
  const CW = 8, RH = 13, X0 = 40, Y0 = 26;            // a column's width, a row's height, margins
  const W = X0 + 80 * CW + 12, H = Y0 + 12 * RH + 40;

  const svg = ParsonsCabinet.svg; // the page's SVG element maker (web/cabinet.js)

  class Reader {
    constructor(box, viewer) {
      this.box = box;
      this.v = viewer;
      this.shown = -2;
    }

    // A new record: the card outline, the wiring by column, each card's instants.
    build() {
      const h = this.v.h;
      this.box.textContent = "";
      this.brushes = h.brushes || [];
      if (!this.brushes.length) return;
      const ids = new Map(h.signals.map((s, i) => [s ? `${s.scope}.${s.name}` : "", i]));
      this.wires = new Map(); // column -> [{rows, field, picks}]
      for (const w of h.brush_wiring || []) {
        if (!this.wires.has(w.column)) this.wires.set(w.column, []);
        this.wires.get(w.column).push(w);
      }
      this.ids = ids;
      // When the reader took each card: the last change of "card in the reader" to its deck
      // position at or before the first bank; when the second bank stepped its speed switches.
      const { change_t, change_id, change_v } = this.v.a;
      const cardSignal = ids.get("cabinet.card_reader_134.card");
      const speedSignals = new Set(h.signals.map((s, i) => (s && s.name === "speed_switch_236" ? i : -1)).filter((i) => i >= 0));
      this.fed = this.brushes.map((b) => b.t);
      this.second = this.brushes.map(() => null);
      const at = new Map(this.brushes.map((b, n) => [b.index, n]));
      let n = -1; // the last card whose first bank came before change i
      for (let i = 0; i < change_t.length; i++) {
        while (n + 1 < this.brushes.length && this.brushes[n + 1].t < change_t[i]) n++;
        if (change_id[i] === cardSignal) {
          const m = at.get(change_v[i]);
          if (m !== undefined && change_t[i] <= this.brushes[m].t) this.fed[m] = change_t[i];
        } else if (n >= 0 && this.second[n] === null && change_v[i] !== 0 && speedSignals.has(change_id[i])) {
          this.second[n] = change_t[i]; // a speed switch's first step after the first bank
        }
      }
      const root = svg("svg", { viewBox: `0 0 ${W} ${H}`, class: "reader", role: "img",
                                "aria-label": "the card in reader 134, its holes, and the two banks of brushes passing over it" }, this.box);
      this.root = root;
      // Card 162: cream, its top-left corner cut, its rows printed.
      svg("path", { d: `M${X0 - 10} ${Y0 - 6}h${80 * CW + 16}v${12 * RH + 12}h${-(80 * CW + 16)}v${-(12 * RH) + 4}z`, class: "reader-card" }, root);
      ROWS.forEach((r, i) => {
        const t = svg("text", { x: X0 - 16, y: Y0 + i * RH + 10, class: "reader-row" }, root);
        t.textContent = String(r);
      });
      for (let c = 10; c <= 80; c += 10) {
        const t = svg("text", { x: X0 + (c - 1) * CW + CW / 2, y: Y0 + 12 * RH + 18, class: "reader-col" }, root);
        t.textContent = String(c);
      }
      this.holes = svg("g", { class: "reader-holes" }, root);
      this.bank1 = svg("line", { x1: X0 - 12, x2: X0 + 80 * CW + 8, class: "reader-brush bank-1" }, root);
      this.bank2 = svg("line", { x1: X0 - 12, x2: X0 + 80 * CW + 8, class: "reader-brush bank-2" }, root);
      this.caption = this.v.doc.createElement("p");
      this.caption.className = "reader-says";
      this.caption.setAttribute("aria-live", "polite");
      this.box.appendChild(this.caption);
      this.cardShown = -2;
      this.lit = [];
      // A hole is a few pixels wide (on a phone five): a tap anywhere on the card explains the
      // hole nearest it, within two columns and a row.
      this.root.addEventListener("click", (e) => {
        const m = this.root.getScreenCTM();
        if (!m) return;
        const p = new DOMPoint(e.clientX, e.clientY).matrixTransform(m.inverse());
        let best = null, bestD = Infinity;
        for (const hole of this.holes.children) {
          const dx = (Number(hole.getAttribute("x")) + (CW - 3) / 2 - p.x) / CW;
          const dy = (Number(hole.getAttribute("y")) + (RH - 5) / 2 - p.y) / RH;
          const d = dx * dx + dy * dy;
          if (d < bestD) { bestD = d; best = hole; }
        }
        if (best && bestD <= 5) this.explain(best);
      });
    }

    // The card in the reader at the instant shown: the last the first bank has begun on.
    update(t) {
      if (!this.root) return;
      // The last card fed at or before t (the cards come in time order): a binary search.
      let lo = 0, hi = this.brushes.length;
      while (lo < hi) {
        const mid = (lo + hi) >> 1;
        if (this.fed[mid] <= t) lo = mid + 1;
        else hi = mid;
      }
      const n = lo - 1;
      if (n !== this.cardShown) {
        this.drawCard(n);
        delete this.root.dataset.state; // the new card's holes take the sensing state below
      }
      const card = this.brushes[n];
      const place = (line, from, to) => {
        if (!card || from === null || to === null || t < from) { line.setAttribute("visibility", "hidden"); return 1; }
        const p = to > from ? Math.min(1, (t - from) / (to - from)) : 1;
        // The card goes in nine-edge first: the brushes meet row 9 first, row 12 last.
        const y = Y0 + 12 * RH - p * 12 * RH;
        line.setAttribute("y1", y.toFixed(1));
        line.setAttribute("y2", y.toFixed(1));
        line.setAttribute("visibility", p < 1 ? "visible" : "hidden");
        return p;
      };
      const p1 = place(this.bank1, card ? this.fed[n] : null, card ? card.t : null);
      const secondEnd = card ? this.second[n] : null;
      place(this.bank2, card ? card.t : null, secondEnd);
      // The rows the first bank has passed: their holes are sensed.
      const sensedRows = card ? Math.floor(p1 * 12 + 1e-9) : 0;
      const state = sensedRows >= 12 ? "sensed" : sensedRows > 0 ? "sensing" : "fed";
      if (this.root.dataset.state !== state || this.root.dataset.rows !== String(sensedRows)) {
        this.root.dataset.state = card ? state : "empty";
        this.root.dataset.rows = String(sensedRows);
        for (const hole of this.holes.children) {
          const row = Number(hole.dataset.rowIndex);
          hole.classList.toggle("sensed", 11 - row < sensedRows);
        }
        this.lightPicks(card && sensedRows > 0);
      }
    }

    drawCard(n) {
      this.cardShown = n;
      this.holes.textContent = "";
      const card = this.brushes[n];
      this.root.dataset.card = card ? String(card.index) : "";
      if (!card) {
        this.caption.textContent = "No card in the reader yet.";
        return;
      }
      let count = 0;
      for (let c = 1; c <= 80; c++) {
        const word = parseInt(card.holes.substr(3 * (c - 1), 3), 16);
        for (let i = 0; i < 12; i++) {
          if (!(word & (0x800 >> i))) continue;
          const hole = svg("rect", { x: X0 + (c - 1) * CW + 1.5, y: Y0 + i * RH + 2.5, width: CW - 3, height: RH - 5,
                                     class: "reader-hole" }, this.holes);
          hole.dataset.column = String(c);
          hole.dataset.row = String(ROWS[i]);
          hole.dataset.rowIndex = String(i);
          const wire = this.wireOf(c, ROWS[i]);
          if (wire) {
            hole.dataset.picks = wire.name;
            hole.dataset.pickId = String(wire.id);
          }
          const label = `column ${c}, row ${ROWS[i]}` + (wire ? `: ${wire.field}, picks ${wire.part}` : ": read by the card's attachment");
          hole.dataset.label = label;
          count++;
        }
      }
      this.caption.textContent = `Card ${card.index} in reader 134: ${count} holes; tap one to see what its brush picks.`;
    }

    // The wire a hole in column c, row r closes: the signal's id and its part in words.
    wireOf(c, r) {
      for (const w of this.wires.get(c) || []) {
        if (!w.rows.includes(r)) continue;
        const name = w.picks.replace("#", String(r));
        const id = this.ids.get(name);
        if (id === undefined) return null;
        const s = this.v.h.signals[id];
        return { name, id, field: w.field, part: s.component + (s.scope === "cabinet" ? "" : ` (${s.scope})`) };
      }
      return null;
    }

    // The parts the sensed holes pick, lit on the panel (and unlit when the card has gone).
    lightPicks(on) {
      for (const e of this.lit) e.classList.remove("brush-picks");
      this.lit = [];
      if (!on) return;
      const panel = this.v.doc.getElementById("panel");
      if (!panel) return;
      if (this.panelOf === undefined || this.panelOf.panel !== panel.firstChild) {
        // The panel's parts by signal, once a panel (it is built again only for new signals).
        this.panelOf = { panel: panel.firstChild, parts: new Map() };
        for (const e of panel.querySelectorAll("[data-signal]")) this.panelOf.parts.set(Number(e.dataset.signal), e);
      }
      for (const hole of this.holes.querySelectorAll(".reader-hole.sensed")) {
        const id = Number(hole.dataset.pickId);
        if (!(id >= 0)) continue;
        const part = this.panelOf.parts.get(id);
        if (part && !part.classList.contains("brush-picks")) {
          part.classList.add("brush-picks");
          this.lit.push(part);
        }
      }
      this.root.dataset.lit = String(this.lit.length);
    }

    // A hole tapped: what it is and what it picks, and that part of the panel shown.
    explain(hole) {
      const c = Number(hole.dataset.column), r = Number(hole.dataset.row);
      const wire = this.wireOf(c, r);
      for (const old of this.holes.querySelectorAll(".chosen")) old.classList.remove("chosen");
      hole.classList.add("chosen");
      this.caption.textContent = wire
        ? `Column ${c}, row ${r} (${wire.field}): its brush picks ${wire.part}.`
        : `Column ${c}, row ${r}: read by the card's attachment, not wired to the 1952 banks.`;
      if (!wire) return;
      const part = this.v.doc.querySelector(`#panel [data-signal="${wire.id}"]`);
      if (part) {
        part.classList.add("brush-chosen");
        setTimeout(() => part.classList.remove("brush-chosen"), 2500);
      }
    }
  }

  return { Reader };
})();
