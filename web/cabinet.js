// The control cabinet as the exhibit page and `parsons run --html` draw it (docs/web.md): a
// column for the shared parts and one an axis, each relay, stepping switch and lamp of the
// record a button labelled by its patent numeral, and a part's story on demand (web/parts.js).
// It shows the values the viewer (web/viewer.js) holds; it computes nothing of the machine.
"use strict";

const ParsonsCabinet = (() => {
  const SVG = "http://www.w3.org/2000/svg";

  // The page's two element makers (the viewer's positions and gauges use them too).
  function el(tag, attrs, parent) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === "text") e.textContent = v;
      else e.setAttribute(k, v);
    }
    if (parent) parent.appendChild(e);
    return e;
  }

  function svg(tag, attrs, parent) {
    const e = document.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
    if (parent) parent.appendChild(e);
    return e;
  }

  // The part's name and numeral (as the C++ defines the signal) and what it does.
  function hover(sig) {
    const does = ParsonsParts.LEGEND[sig.numeral] || "";
    return `${sig.component}${sig.numeral ? " (" + sig.numeral + ")" : ""}` + (does ? `: ${does}` : "");
  }

  // The digit place each bank of holding relays holds (relaylogic/storage.hpp), for the
  // visitor's voice: absolute 350-356 (where to slow down and stop), incremental 324-318 (the move).
  const BANK_PLACE = { 350: "inch", 352: "tenth", 354: "hund.", 356: "thou.", 324: "inch", 322: "tenth", 320: "hund.", 318: "thou." };
  // A counter's stepping switch by the digit it counts (its component names it, counters.cpp).
  const SHORT_PLACE = { inches: "inch", tenths: "tenth", hundredths: "hund.", thousandths: "thou." };

  // Every part of the cabinet is reached by keyboard (Tab) and touch, not by the mouse's hover
  // alone: a focusable button with its name; data-short is the numeral the compact panel of a
  // wide screen shows in place of the long label (web/exhibit.css).
  function reachable(e, sig, more = "") {
    const name = sig.component + (sig.numeral && !sig.component.includes(sig.numeral) ? ` (${sig.numeral})` : "") + more;
    e.setAttribute("tabindex", "0");
    e.setAttribute("role", "button");
    e.setAttribute("aria-label", `${sig.scope === "cabinet" ? "shared" : sig.scope}: ${name}`);
    const set = /\.contact_set_([ab])$/.exec(sig.name);
    const dot = /\.([a-z_]+)$/.exec(sig.name);
    e.dataset.short = sig.numeral ? sig.numeral + (set ? set[1].toUpperCase() : dot && !/\d/.test(dot[1]) ? " " + dot[1] : "")
      : sig.name.replace(/_/g, " ");
  }

  class Cabinet {
    // viewer: the record (h), the values now, machine time (t), the document and its $.
    constructor(viewer) {
      this.v = viewer;
      this.key = null;
      this.updaters = [];
    }

    // Every part drawn at its value now.
    renderAll() {
      this.updaters.forEach((u, id) => { if (u) u(this.v.values[id]); });
      this.renderPlain();
    }

    // The parts of these signals drawn at their values now.
    render(ids) {
      for (const id of ids) { const u = this.updaters[id]; if (u) u(this.v.values[id]); }
      this.renderPlain();
    }

    // The panel of the viewer's record (viewer.h): built again only when its signals change.
    build() {
      // The same machine profile defines the same signals: the panel built for the last run
      // serves again.
      const key = this.v.h.signals.map((s) => (s ? `${s.scope}.${s.name}` : "")).join(",");
      if (key === this.key) return;
      this.key = key;
      const panel = this.v.$("panel");
      panel.textContent = "";
      this.updaters = new Array(this.v.h.signals.length);
      this.plainLines = new Map();
      this.ids = new Map(); // "scope.name" -> signal id, for the plain lines
      this.v.h.signals.forEach((s, id) => { if (s) this.ids.set(`${s.scope}.${s.name}`, id); });
      this.voiceButton();
      const scopes = new Map();
      this.v.h.signals.forEach((s, id) => {
        if (!s) return;
        if (!scopes.has(s.scope)) scopes.set(s.scope, []);
        scopes.get(s.scope).push({ ...s, id });
      });
      const order = ["cabinet", ...this.v.h.axes];
      const scopeNames = [...order.filter((s) => scopes.has(s)), ...[...scopes.keys()].filter((s) => !order.includes(s))];
      for (const scope of scopeNames) {
        const col = el("div", { class: "scope", "data-scope": scope }, panel);
        el("h3", { text: scope === "cabinet" ? "shared" : scope }, col);
        this.plainLines.set(scope, el("p", { class: "plain-line" }, col)); // the visitor's voice
        const banks = new Map();
        const dials = [];
        const singles = [];
        for (const s of scopes.get(scope)) {
          const relay = /^(.*)\.relay_(\d+)$/.exec(s.name);
          if (relay) {
            if (!banks.has(relay[1])) banks.set(relay[1], []);
            banks.get(relay[1]).push({ ...s, digit: Number(relay[2]) });
          } else if (/counter_\d+$/.test(s.name) && s.width >= 4) {
            dials.push(s);
          } else {
            singles.push(s);
          }
        }
        if (dials.length) this.buildDials(col, dials);
        if (banks.size) this.buildBanks(col, banks);
        if (singles.length) this.buildSingles(col, singles);
      }
      if (!this.partsBound) {
        // A part clicked, tapped, or pressed with Enter or Space tells its story in #part-info.
        this.partsBound = true;
        const choose = (e) => {
          // A bank's row is one target as wide as the column (on a touch screen 44 px tall):
          // a tap anywhere on it tells the bank's story, as its relays do.
          const bank = e.type === "click" ? e.target.closest(".bank") : null;
          const part = e.target.closest("[data-signal]") || (bank && bank.querySelector(".relay"));
          if (!part) return;
          e.preventDefault();
          this.showPart(part);
        };
        panel.addEventListener("click", choose);
        panel.addEventListener("keydown", (e) => { if (e.key === "Enter" || e.key === " ") choose(e); });
      }
      this.shownPart = null;
      this.v.$("part-info").hidden = true;
      this.setVoice(this.v.doc.getElementById("voice").getAttribute("aria-pressed") === "true");
    }

    buildBanks(col, banks) {
      const box = el("div", { class: "banks" }, col);
      for (const [name, relays] of banks) {
        const first = relays[0];
        const numeral = first.numeral;
        const row = el("div", { class: "bank", title: hover(first), "data-bank": name }, box);
        el("span", { class: "label", text: numeral, "data-numeral": numeral, "data-plain": BANK_PLACE[numeral] || numeral }, row);
        relays.sort((a, b) => a.digit - b.digit);
        for (const r of relays) {
          const lamp = el("span", { class: "relay", "data-signal": r.id, text: String(r.digit) }, row);
          reachable(lamp, r, `, relay of digit ${r.digit}`);
          this.updaters[r.id] = (v) => lamp.classList.toggle("on", v !== 0);
        }
      }
    }

    buildDials(col, dials) {
      const box = el("div", { class: "dials" }, col);
      for (const d of dials) {
        const numeral = d.numeral;
        const wrap = el("div", { class: "dial", title: hover(d), "data-signal": d.id, "data-name": d.name }, box);
        reachable(wrap, d);
        const s = svg("svg", { viewBox: "-22 -22 44 44", width: 44, height: 44 }, wrap);
        svg("circle", { r: 20, class: "face" }, s);
        for (let k = 0; k < 10; k++) {
          const a = (k / 10) * 2 * Math.PI;
          const tx = svg("text", { x: (15 * Math.sin(a)).toFixed(2), y: (-15 * Math.cos(a) + 2.5).toFixed(2), class: "tick" }, s);
          tx.textContent = String(k);
        }
        const hand = svg("line", { x1: 0, y1: 0, x2: 0, y2: -10, class: "hand" }, s);
        const place = SHORT_PLACE[(/\((\w+)\)$/.exec(d.component) || [])[1]] || numeral;
        el("span", { class: "label", text: numeral, "data-numeral": numeral, "data-plain": place }, wrap);
        this.updaters[d.id] = (v) => {
          hand.setAttribute("transform", `rotate(${v * 36})`);
          wrap.dataset.value = String(v);
        };
      }
    }

    buildSingles(col, singles) {
      const box = el("div", { class: "singles" }, col);
      for (const s of singles) {
        const lamp = el("span", { class: "lamp" + (/lamp|indicator/.test(s.name) ? " signal-lamp" : ""), title: hover(s), "data-signal": s.id, "data-name": s.name }, box);
        reachable(lamp, s);
        const label = s.name.replace(/_/g, " ");
        if (s.width > 1) {
          el("span", { class: "label", text: label + " " }, lamp);
          const v = el("b", {}, lamp);
          this.updaters[s.id] = (x) => { v.textContent = String(x); lamp.classList.toggle("on", x !== 0); };
        } else {
          lamp.textContent = label;
          this.updaters[s.id] = (x) => lamp.classList.toggle("on", x !== 0);
        }
      }
    }

    // ---- a part's story: what it is, what it does, the patent's words, and its state now

    // part: a relay (its bank is the part), a dial or a lamp of the panel.
    showPart(el0) {
      const part = el0.classList.contains("relay") ? el0.closest(".bank") : el0;
      const id = Number(el0.dataset.signal);
      const sig = this.v.h.signals[id];
      const box = this.v.$("part-info");
      for (const old of this.v.doc.querySelectorAll("#panel .chosen")) old.classList.remove("chosen");
      part.classList.add("chosen");
      this.shownPart = part;
      this.shownSignal = id;
      box.textContent = "";
      const where = sig.scope === "cabinet" ? "the shared cabinet" : `the ${sig.scope} axis`;
      const bank = part.classList.contains("bank");
      el("h3", { text: `${bank ? "storage bank" : sig.component} ${sig.numeral} · ${where}` }, box);
      el("p", { text: ParsonsParts.LEGEND[sig.numeral] || "" }, box);
      const [fig, words] = ParsonsParts.passage(sig.numeral);
      if (words) el("blockquote", { text: `“${words}”` }, box);
      el("p", { class: "fig", text: `US 2,820,187, ${fig}` }, box);
      this.partState = el("p", { class: "live" }, box);
      const close = el("button", { type: "button", class: "close", text: "Close" }, box);
      close.addEventListener("click", () => {
        box.hidden = true;
        part.classList.remove("chosen");
        this.shownPart = null;
        el0.focus();
      });
      box.hidden = false;
      this.renderPart();
    }

    // ---- two voices (issue 52, item 4): the engineer's numerals, or the visitor's plain words on
    // the panel itself, one switch above it. The plain words say what the relays and switches
    // stand at now, read from the record (its values and its cards' orders): nothing here
    // decides anything, not even which readings a bank's relays close the circuit for.

    voiceButton() {
      const doc = this.v.doc;
      let b = doc.getElementById("voice");
      if (!b) {
        b = el("button", { type: "button", id: "voice", "aria-pressed": "false", text: "Plain words" });
        this.v.$("panel").before(b);
        b.addEventListener("click", () => this.setVoice(b.getAttribute("aria-pressed") !== "true"));
      }
    }

    setVoice(plain) {
      const doc = this.v.doc;
      doc.body.dataset.voice = plain ? "visitor" : "engineer";
      const b = doc.getElementById("voice");
      b.setAttribute("aria-pressed", String(plain));
      b.textContent = plain ? "Numerals" : "Plain words";
      b.title = plain ? "Show the patent's numerals" : "Say on the panel, in plain words, what each part stands at";
      for (const l of this.v.$("panel").querySelectorAll(".label[data-plain]")) {
        l.textContent = plain ? l.dataset.plain : l.dataset.numeral;
      }
      this.renderPlain();
    }

    // Whether any relay of these banks of holding relays is closed now (the record's values).
    anyClosed(scope, banks) {
      return banks.some((b) => {
        for (let d = 0; d < 10; d++) if (this.v.values[this.ids.get(`${scope}.${b}.relay_${d}`)]) return true;
        return false;
      });
    }

    renderPlain() {
      if (!this.plainLines || this.v.doc.body.dataset.voice !== "visitor") return;
      const val = (scope, name) => this.v.values[this.ids.get(`${scope}.${name}`)];
      for (const [scope, line] of this.plainLines) {
        if (scope === "cabinet") {
          const card = val(scope, "card_reader_134.card");
          line.textContent = `${card ? `card ${card} in the reader` : "no card read yet"}; the sequence shaft at step ` +
            `${val(scope, "stepping_shaft_280")}; the master switch ${val(scope, "master_switch_204") ? "closed: motors may run" : "open: the machine is stopped"}.`;
          continue;
        }
        if (val(scope, "speed_switch_236") === undefined) continue;
        // What the storage holds is what the card in the reader gave it (the record's card
        // orders), while its relays stand closed: between the relays picking and zeroizing.
        const card = this.v.cardIndex >= 0 ? this.v.h.cards[this.v.cardIndex] : null;
        const orders = card && card.axes ? card.axes[scope] : null;
        const n = (x) => x.toFixed(3);
        const held = orders && this.anyClosed(scope, ["absolute_storage_350", "absolute_storage_352", "absolute_storage_354", "absolute_storage_356"])
          ? orders.held_in.map(n) : [];
        const move = orders && this.anyClosed(scope, ["incremental_storage_324", "incremental_storage_322", "incremental_storage_320", "incremental_storage_318"])
          ? [n(orders.check_in)] : [];
        const speed = val(scope, "speed_switch_236");
        line.textContent = `counts ${this.v.counterReading(scope)} in; ` +
          (held.length ? `holds the number${held.length > 1 ? "s" : ""} ${held.join(", ")} (slow down, stop)` : "holds no number") +
          `; the move ${move.length ? move[0] + " in" : "not set"}; ` +
          `speed ${speed ? speed + (speed === 3 ? " (fast)" : speed === 1 ? " (slow)" : "") : "off"}.`;
      }
    }

    renderPart() {
      const part = this.shownPart;
      if (!part) return;
      let now;
      if (part.classList.contains("bank")) {
        const closed = [...part.querySelectorAll(".relay")].filter((r) => this.v.values[Number(r.dataset.signal)] !== 0)
          .map((r) => r.textContent);
        now = closed.length ? `relay${closed.length > 1 ? "s" : ""} ${closed.join(", ")} closed` : "every relay open";
      } else {
        const v = this.v.values[this.shownSignal];
        now = part.classList.contains("dial") || this.v.h.signals[this.shownSignal].width > 1 ? `stands at ${v}`
          : v ? "closed (on)" : "open (off)";
      }
      this.partState.textContent = `Now, at ${this.v.t.toFixed(3)} s: ${now}.`;
    }
  }

  return { Cabinet, el, svg };
})();
