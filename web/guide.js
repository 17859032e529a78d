// After the tour, a next step (issue 52, item 5): punch your own card. A short form under the
// tour ("make the table move 2.000 inches") becomes a one-line G-code program, which parsons'
// own generator (`parsons gen gcode`) turns into cards by the 1952 slow-down rule (speeds and
// slow-downs as the machine needs them, no shared-bank match on the way); the page puts them in
// the keypunch, runs them and plays them. Nothing of the machine or of the generator is
// written here: only the program line.
"use strict";

const ParsonsGuide = (() => {
  const LETTER = { table: "X", cross: "Y", vertical: "Z" }; // gen gcode: X table, Y cross, Z vertical

  // The program: inches, absolute, one straight move from the work zero.
  function program(axis, inches) {
    return `(your own card: the ${axis} moves ${String(inches).trim()} in)\nG20 G90\nG1 ${LETTER[axis]}${String(inches).trim()}\nM2\n`;
  }

  // tour: the viewer's tour (its box and onEnd); punchAndRun(program): the page generates the
  // cards from it, punches, runs and plays them.
  function install(doc, tour, punchAndRun) {
    const box = doc.createElement("section");
    box.id = "next-step";
    box.hidden = true;
    box.setAttribute("aria-live", "polite");
    box.innerHTML = `<h3>Now punch your own card</h3>
      <form id="guide-form">
        <label>Make the <select id="guide-axis">${Object.keys(LETTER).map((a) => `<option>${a}</option>`).join("")}</select></label>
        <label>move <input id="guide-inches" value="2.000" size="6" inputmode="decimal" aria-label="inches"> inches</label>
        <button type="submit" id="guide-go">Punch it and run</button>
        <button type="button" id="guide-close">No, thanks</button>
      </form>
      <p class="hint">parsons' generator punches the card as the 1952 planners did (the speed and its slow-downs
      by the slow-down rule); the keypunch then holds it, and the machine reads it, moves and stops where you said.</p>`;
    tour.box.after(box);
    tour.onEnd = () => {
      box.hidden = false;
      doc.getElementById("guide-inches").focus({ preventScroll: true });
      box.scrollIntoView({ block: "nearest" });
    };
    doc.getElementById("guide-close").addEventListener("click", () => { box.hidden = true; });
    doc.getElementById("guide-form").addEventListener("submit", (e) => {
      e.preventDefault();
      punchAndRun(program(doc.getElementById("guide-axis").value, doc.getElementById("guide-inches").value));
    });
  }

  return { install, program };
})();
