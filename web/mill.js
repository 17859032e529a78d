// The mill, drawn (issue 52, item 1): the machine of the patent's Figs. 1-3 seen from above, an
// SVG that moves with the recorded run. Bed plate 10 with its rails 12; table 14 sliding along
// them (lead screw 22); on the table the universal fixture, bottom member 15 swivelling about its
// pivot (screw 26) and sine plate 16 tilting about hinge 19 (screws 24, seen foreshortened from
// above); uprights 18-18 and cross member 20 bridging the bed; crosshead 32 with cutter head 28
// and cutter 30 travelling across it (screw 36; screws 34 raise it, shown by the gauge beside).
// The cut appears on the table as it is made: the cutter-centre path of the record, drawn in the
// table's frame, so it rides with the table under the cutter as on the machine.
//
// Every position comes from the record's motion (RunTimeline's eight numbers a record, the
// machine's own): nothing here is a rule of the machine, only where to draw what it did.
"use strict";

const ParsonsMill = (() => {
  const NS = "http://www.w3.org/2000/svg";
  const W = 640, H = 300;      // the drawing's units
  const X0 = 320;              // the crosshead's place along the bed, where the cutter cuts
  const MOST_CHUNKS = 150;     // cut pieces before they are joined into one path

  function svg(tag, attrs, parent) {
    const e = document.createElementNS(NS, tag);
    for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
    if (parent) parent.appendChild(e);
    return e;
  }
  function label(parent, x, y, text, cls = "mill-label") {
    const t = svg("text", { x, y, class: cls }, parent);
    t.textContent = text;
    return t;
  }

  class Mill {
    // box: the element the drawing goes in; viewer: the record (a.motion, pathDrawn, radius).
    constructor(box, viewer) {
      this.box = box;
      this.v = viewer;
    }

    // A new record: the drawing scaled to its table and cross travel.
    build() {
      const m = this.v.a.motion;
      let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
      for (let i = 0; i < m.length; i += 8) {
        x0 = Math.min(x0, m[i + 1]); x1 = Math.max(x1, m[i + 1]);
        y0 = Math.min(y0, m[i + 2]); y1 = Math.max(y1, m[i + 2]);
      }
      if (!isFinite(x0)) { x0 = 0; x1 = 1; y0 = 0; y1 = 1; }
      const xr = Math.max(x1 - x0, 0.5), yr = Math.max(y1 - y0, 0.5);
      const s = Math.min((W - 60) / (2 * xr + 0.6), 150 / yr); // drawing units an inch
      const margin = 0.3 * s;
      this.s = s;
      this.cy = 150 + ((y0 + y1) / 2) * s; // the cross travel centred across the bed
      this.box.textContent = "";
      const root = svg("svg", { viewBox: `0 0 ${W} ${H}`, class: "mill", role: "img",
                                "aria-label": "the milling machine from above: bed, table, fixture, bridge and cutter, moving with the run" }, this.box);
      this.root = root;
      // Bed plate 10 and rails 12: long enough for the table's whole travel.
      const bedHalf = xr * s + margin + 24;
      svg("rect", { x: X0 - bedHalf, y: 40, width: 2 * bedHalf, height: 220, rx: 6, class: "mill-bed" }, root);
      for (const y of [70, 230]) svg("line", { x1: X0 - bedHalf + 6, y1: y, x2: X0 + bedHalf - 6, y2: y, class: "mill-rail" }, root);
      label(root, X0 - bedHalf + 8, 62, "bed 10, rails 12");
      // Table 14 and what rides on it: its frame is the cut's (table position x at x s).
      this.table = svg("g", { class: "mill-table" }, root);
      const tx0 = x0 * s - margin, tw = xr * s + 2 * margin;
      svg("rect", { x: tx0, y: 60, width: tw, height: 180, rx: 3, class: "mill-table-top" }, this.table);
      label(this.table, tx0 + 6, 256, "table 14");
      // The fixture: bottom member 15 swivels about its pivot at the table's left end; sine
      // plate 16 on it tilts about hinge 19 (its length foreshortened from above).
      this.pivot = [tx0 + 14, 150];
      this.fixture = svg("g", {}, this.table);
      svg("rect", { x: tx0 + 8, y: 78, width: tw - 16, height: 144, class: "mill-member-15" }, this.fixture);
      svg("circle", { cx: this.pivot[0], cy: this.pivot[1], r: 3, class: "mill-pivot" }, this.fixture);
      this.plate = svg("rect", { x: tx0 + 16, y: 86, width: tw - 32, height: 128, class: "mill-plate-16" }, this.fixture);
      this.plateLength = tw - 32;
      svg("line", { x1: tx0 + 16, y1: 86, x2: tx0 + 16, y2: 214, class: "mill-hinge" }, this.fixture);
      label(this.fixture, tx0 + 22, 110, "sine plate 16, hinge 19");
      // The design (an airfoil template job) and the path the run takes, faint, then the cut.
      const design = this.v.h.design && this.v.h.design.points ? this.v.h.design.points : [];
      if (design.length) {
        svg("path", { d: "M" + design.map((p) => this.at(p[0], p[1]).map((n) => n.toFixed(1)).join(" ")).join("L"),
                      class: "mill-design" }, this.table);
      }
      this.ahead = svg("path", { d: this.pathD(0, m.length / 8 - 1), class: "mill-ahead" }, this.table);
      this.cut = svg("g", { class: "mill-cut" }, this.table);
      if (this.v.radius > 0) this.cut.style.strokeWidth = String(Math.max(1, 2 * this.v.radius * s)); // the cutter's width
      this.chunks = 0;
      this.cutTo = 0; // records drawn into the cut
      // Uprights 18-18, cross member 20 and crosshead 32 bridge the bed at X0.
      svg("rect", { x: X0 - 22, y: 6, width: 44, height: 26, class: "mill-upright" }, root);
      svg("rect", { x: X0 - 22, y: 268, width: 44, height: 26, class: "mill-upright" }, root);
      label(root, X0 + 26, 26, "upright 18");
      svg("rect", { x: X0 - 9, y: 20, width: 18, height: 260, class: "mill-crosshead" }, root);
      label(root, X0 + 26, 290, "bridge 20, crosshead 32");
      // Cutter head 28 and cutter 30, travelling across on the crosshead (screw 36).
      this.head = svg("g", {}, root);
      svg("rect", { x: X0 - 16, y: -14, width: 32, height: 28, rx: 4, class: "mill-head" }, this.head);
      this.cutter = svg("circle", { cx: X0, cy: 0, r: Math.max(4, this.v.radius * s), class: "mill-cutter" }, this.head);
      label(this.head, X0 + 20, 6, "head 28, cutter 30");
      this.shown = -1;
    }

    // Record point (table, cross) in the table's frame.
    at(x, y) { return [x * this.s, this.cy - y * this.s]; }

    // Path data through records from .. to, the points the viewer draws (its pathDrawn).
    pathD(from, to) {
      const m = this.v.a.motion, drawn = this.v.pathDrawn;
      if (to < from || to < 0) return "";
      const pts = [];
      for (let k = from; k <= to; k++) {
        if (k === from || k === to || !drawn || drawn[k]) {
          const [x, y] = this.at(m[8 * k + 1], m[8 * k + 2]);
          pts.push(`${x.toFixed(1)} ${y.toFixed(1)}`);
        }
      }
      return pts.length > 1 ? "M" + pts.join("L") : "";
    }

    // The machine at record mi (the number of records at or before the instant shown).
    update(mi) {
      if (!this.root) return;
      const m = this.v.a.motion;
      if (mi < this.cutTo) this.clearCut();
      if (mi > this.cutTo) {
        if (this.chunks >= MOST_CHUNKS) {
          this.clearCut();
        }
        const d = this.pathD(Math.max(0, this.cutTo - 1), mi - 1);
        if (d) { svg("path", { d }, this.cut); this.chunks++; }
        this.cutTo = mi;
      }
      if (mi === this.shown) return;
      this.shown = mi;
      const k = Math.max(0, mi - 1) * 8;
      const have = mi > 0;
      const table = have ? m[k + 1] : 0, cross = have ? m[k + 2] : 0;
      const swivel = have ? m[k + 6] : 0, tilt = have ? m[k + 7] : 0;
      this.table.setAttribute("transform", `translate(${(X0 - table * this.s).toFixed(2)} 0)`);
      this.fixture.setAttribute("transform", `rotate(${(-swivel).toFixed(3)} ${this.pivot[0]} ${this.pivot[1]})`);
      this.plate.setAttribute("width", (this.plateLength * Math.cos(tilt * Math.PI / 180)).toFixed(2));
      this.head.setAttribute("transform", `translate(0 ${(this.cy - cross * this.s).toFixed(2)})`);
      this.root.dataset.table = table.toFixed(5);
      this.root.dataset.cross = cross.toFixed(5);
      this.root.dataset.cutRecords = String(this.cutTo);
    }

    clearCut() {
      this.cut.textContent = "";
      this.chunks = 0;
      this.cutTo = 0;
    }
  }

  return { Mill };
})();
