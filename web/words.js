// A deck error in a visitor's words (issue 52, defect 4): the card and axis the visitor wrote (a
// listing line is a row of the keypunch), what is wrong in plain words, the row with the bad
// cell marked; parsons' exact words one click away. Only words: what is wrong is always
// parsons' own finding, and a message with no plain words here is said as parsons says it.
"use strict";

const ParsonsWords = (() => {
  const LISTING_FIELDS = ["card", "spindle", "axis", "motion", "speed", "slow1", "slow2", "stop", "check", "seq"];
  const PLAIN = [
    [/^speed '([^']*)' is not 1, 2 or 3/, (v) => `speed ${v || "blank"}: the machine has speeds 1, 2 and 3`],
    [/^motion '([^']*)' is not/, (v) => `motion ${v || "blank"}: an axis moves + (forward) or - (back)`],
    [/^spindle '([^']*)' is not/, (v) => `spindle ${v}: the spindle runs 0 (forward), 1 (reverse) or blank (off)`],
    [/^unknown axis '([^']*)'/, (v) => `there is no axis "${v}": the machine has table, cross, vertical, swivel and tilt`],
    [/^card number '([^']*)' is not/, (v) => `card number ${v}: a card number is 0 to 9999`],
    [/^(stop|check) is blank/, (v) => `the ${v} is empty: every axis needs its stop and its check`],
    [/^sequence position '([^']*)' is not/, (v) => `sequence ${v}: the sequence positions are 1 to 5`],
    [/^(\w+) '([^']*)': not a number of inches/, (f, v) => `${f} ${v}: inches are written d.ddd, e.g. 8.785`],
    [/^(\w+) '([^']*)': needs exactly three decimals/, (f, v) => `${f} ${v}: the card holds thousandths, so three decimals, d.ddd`],
    [/^(\w+) '([^']*)': over 9\.999 inches/, (f, v) => `${f} ${v}: the counters go up to 9.999 inches`],
    [/^(\w+) '([^']*)': inches are never negative/, (f, v) => `${f} ${v}: inches are never negative (the motion column gives the way)`],
  ];
  const FILE_WORDS = [
    [/parity error/, (c) => `card ${c} has a column whose holes fail the file's check bit`],
    [/card-start mark \(bit 7\) inside the card/, (c) => `card ${c} is shorter than a card`],
    [/no card-start mark/, (c) => `card ${c} does not begin where a card begins`],
    [/truncated card/, (c) => `the file ends in the middle of card ${c}`],
  ];
  // The elements that say `text` (parsons' error) to a visitor: the lead, the row with its bad
  // cell marked (withRow: not under the field table, whose cell is marked) and the exact words.
  // listingName: the keypunch's file as parsons names it; listingText: what it holds.
  function explained(doc, text, { listingName, listingText, withRow = true }) {
    const first = text.split("\n")[0].replace(/^parsons: error: /, "");
    const lead = doc.createElement("p");
    lead.className = "visitor-words";
    const parts = [lead];
    const m = first.match(new RegExp(`${listingName.replace(".", "\\.")}:(\\d+):\\s*(.*)$`));
    if (m) {
      const row = (listingText.split("\n")[Number(m[1]) - 1] || "").split(",");
      const axis = row[1] === "if" ? row[3] : row[2];
      const said = m[2];
      let plain = said.replace(/'([^']*)'/g, "$1");
      for (const [re, words] of PLAIN) {
        const w = said.match(re);
        if (w) { plain = words(...w.slice(1)); break; }
      }
      const where = row.length > 2 && /^\d+$/.test(row[0].trim())
        ? `Card ${Number(row[0])}${axis ? `, ${axis.trim()}` : ""}` : `Line ${m[1]} of the listing`;
      lead.textContent = `${where}: ${plain}.`;
      // The row as written, its bad cell marked.
      const bad = badField(said, row);
      if (withRow && row.length > 1) {
        const code = doc.createElement("code");
        code.className = "bad-row";
        row.forEach((cell, i) => {
          if (i) code.append(",");
          if (i === bad) {
            const mark = doc.createElement("mark");
            mark.textContent = cell === "" ? "\u2423" : cell; // an empty cell shown as ␣
            code.append(mark);
          } else code.append(cell);
        });
        parts.push(code);
      }
    } else if (/your-card\.ngc:\d+: /.test(first)) {
      // The card the visitor asked for after the tour (web/guide.js), refused by the generator.
      const said = first.replace(/^.*your-card\.ngc:\d+: /, "");
      lead.textContent = "Your card: " + (/which hold 0 to 9\.999 in/.test(said)
        ? "that move does not fit: the counters hold 0 to 9.999 inches."
        : /no number after it|not a number/.test(said) ? "the inches must be a number, e.g. 2.000." : said);
    } else if (FILE_WORDS.some(([re]) => re.test(first))) {
      const file = first.split(": card ")[0];
      const card = (first.match(/: card (\d+)/) || [])[1] || "1";
      const [, what] = FILE_WORDS.find(([re]) => re.test(first));
      lead.textContent = `${file} is not a deck parsons can read: ${what(card)}, or the file is not a deck of punched ` +
        "cards at all (decks are .cbn, .bin, .txt, .csv, .tape and .five files).";
    } else lead.textContent = first;
    const more = doc.createElement("details");
    const summary = doc.createElement("summary");
    summary.textContent = "parsons' exact words";
    const exact = doc.createElement("pre");
    exact.className = "exact";
    exact.textContent = text;
    more.append(summary, exact);
    parts.push(more);
    return parts;
  }
  // The field of the row the message is about: named in it, or holding the value it quotes.
  function badField(said, row) {
    const lower = said.toLowerCase();
    const named = /^sequence/.test(lower) ? LISTING_FIELDS.indexOf("seq")
      : LISTING_FIELDS.findIndex((f) => new RegExp(`^(unknown )?${f}\\b`).test(lower));
    if (named >= 0 && named < row.length) return named;
    const quoted = (said.match(/'([^']*)'/) || [])[1];
    const at = quoted === undefined ? -1 : row.findIndex((c) => c.trim() === quoted);
    return at;
  }

  return { explained };
})();
