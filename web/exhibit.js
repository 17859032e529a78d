// The exhibit page, live (docs/web.md): the keypunch, the generator and the downloads. Every
// question about a deck goes to the emulator compiled to WebAssembly (web/parsons_web.cpp) as
// the command line a user would type, `parsons show`, `punch`, `convert`, `gen airfoil`,
// `run`, on the page's in-memory files; the page shows what parsons printed and plays the run
// it recorded (web/viewer.js).
"use strict";

(async () => {
  const $ = (id) => document.getElementById(id);
  const status = $("machine-status");
  const viewer = new ParsonsViewer.Viewer(document);
  window.parsonsViewer = viewer;

  let out = [];
  let err = [];
  let M;
  try {
    M = await createParsons({ print: (l) => out.push(l), printErr: (l) => err.push(l) });
  } catch (e) {
    status.dataset.state = "error";
    status.textContent = `The machine could not be loaded: ${e}`;
    return;
  }

  // `parsons ARGS...`: its exit code and what it printed.
  function parsons(args, record = false) {
    out = [];
    err = [];
    let code;
    try {
      code = M.call(JSON.stringify(args), record);
    } catch (e) {
      // The module itself failed (out of memory, say): say so, as the program would, exit 1.
      err.push(`parsons: internal error: ${e} (please report this)`);
      code = 1;
    }
    return { code, out: out.join("\n"), err: err.join("\n") };
  }
  // For the console and the tests: parsonsCall(["show", "/work/deck.csv"]).
  window.parsonsCall = parsons;
  const FS = M.FS;
  const readText = (path) => FS.readFile(path, { encoding: "utf8" });
  const exists = (path) => FS.analyzePath(path).exists;
  function clearFolder(dir) {
    if (!exists(dir)) { FS.mkdir(dir); return; }
    for (const f of FS.readdir(dir)) if (f !== "." && f !== "..") FS.unlink(`${dir}/${f}`);
  }
  FS.mkdir("/work");
  FS.mkdir("/work/load");
  FS.mkdir("/work/load/in");
  FS.mkdir("/work/gen");

  const LISTING = "/work/deck.csv";
  const DECK = "/work/deck.cbn";
  const REPORT = "/work/report.json";
  const MOST_DRAWN_ROWS = 5000; // about 1000 cards
  const listing = $("listing");
  const deckError = $("deck-error");
  let punched = false;   // /work/deck.cbn holds the listing's cards
  let ran = false;       // the viewer holds the run of those cards
  let job = null;        // the job description of a generated deck, while its listing is untouched
  let generatedText = null;

  function showError(text) {
    deckError.hidden = !text;
    deckError.textContent = text || "";
  }

  // ---- the keypunch: every change is punched and drawn at once

  function punchListing() {
    FS.writeFile(LISTING, listing.value);
    punched = false;
    ran = false;
    setDownloads();
    clearFolder("/work/cards");
    // A long deck is shown but not drawn: a picture a card would fill the page's memory.
    const rows = listing.value.split("\n").filter((l) => l.trim() && !l.trimStart().startsWith("#")).length;
    const draw = rows <= MOST_DRAWN_ROWS;
    const shown = parsons(["show", LISTING, ...(draw ? ["--svg", "/work/cards"] : [])]);
    $("deck-show").textContent = shown.out;
    drawCards(draw);
    if (shown.code !== 0) {
      showError(shown.err);
      return false;
    }
    const p = parsons(["punch", LISTING, "-o", DECK]);
    if (p.code !== 0) {
      showError(p.err);
      return false;
    }
    showError("");
    punched = true;
    if (job && listing.value !== generatedText) job = null; // edited: no longer the generated deck
    setDownloads();
    if ($("fields").hidden === false) buildFields();
    return true;
  }

  function drawCards(draw) {
    const box = $("cards");
    for (const img of box.querySelectorAll("img")) URL.revokeObjectURL(img.src);
    box.textContent = "";
    if (!draw) {
      box.textContent = `A deck this long is not drawn here (more than ${MOST_DRAWN_ROWS} rows); ` +
        "parsons show --svg draws every card.";
      return;
    }
    const files = FS.readdir("/work/cards").filter((f) => f.endsWith(".svg")).sort();
    for (const f of files.slice(0, 200)) {
      const fig = document.createElement("figure");
      const img = document.createElement("img");
      img.alt = f;
      img.src = URL.createObjectURL(new Blob([FS.readFile(`/work/cards/${f}`)], { type: "image/svg+xml" }));
      const cap = document.createElement("figcaption");
      cap.textContent = f.replace(".svg", "");
      fig.append(img, cap);
      box.appendChild(fig);
    }
    if (files.length > 200) {
      const more = document.createElement("p");
      more.textContent = `… and ${files.length - 200} more cards (download the deck to see them all).`;
      box.appendChild(more);
    }
  }

  let typing = null;
  listing.addEventListener("input", () => {
    clearTimeout(typing);
    typing = setTimeout(punchListing, 250);
  });

  function setListing(text) {
    listing.value = text;
    punchListing();
  }

  // Field by field: the listing's rows as a table of cells; the listing stays what is punched.
  function buildFields() {
    const box = $("fields");
    box.textContent = "";
    const lines = listing.value.split("\n");
    const table = document.createElement("table");
    let header = null;
    lines.forEach((line, n) => {
      if (line.trim() === "" || line.trimStart().startsWith("#")) return;
      const cells = line.split(",");
      const tr = table.insertRow();
      if (!header) {
        header = cells;
        for (const c of cells) { const th = document.createElement("th"); th.textContent = c; tr.appendChild(th); }
        return;
      }
      cells.forEach((c, i) => {
        const td = tr.insertCell();
        const input = document.createElement("input");
        input.value = c;
        input.setAttribute("aria-label", `line ${n + 1} ${header[i] || ""}`);
        input.dataset.line = String(n);
        input.dataset.cell = String(i);
        input.addEventListener("change", () => {
          const all = listing.value.split("\n");
          const row = all[n].split(",");
          row[i] = input.value;
          all[n] = row.join(",");
          listing.value = all.join("\n");
          punchListing();
        });
        td.appendChild(input);
      });
    });
    box.appendChild(table);
  }
  function tab(which) {
    $("tab-listing").setAttribute("aria-selected", String(which === "listing"));
    $("tab-fields").setAttribute("aria-selected", String(which === "fields"));
    listing.hidden = which !== "listing";
    $("fields").hidden = which !== "fields";
    if (which === "fields") buildFields();
  }
  $("tab-listing").addEventListener("click", () => tab("listing"));
  $("tab-fields").addEventListener("click", () => tab("fields"));

  // ---- decks in: the samples, the demo deck, a file

  $("load-sample").addEventListener("click", () => {
    job = null;
    setListing(readText("/share/parsons/samples/patent-example.csv"));
  });

  // The deck `parsons demo` generates and runs: NACA 2412, 6 in chord, cutter radius 0.25 in,
  // scallop 0.002 in.
  $("load-demo").addEventListener("click", () => generate(["--naca", "2412", "--chord", "6", "--cutter-radius", "0.25", "--scallop", "0.002"]));

  $("load-file").addEventListener("change", async (e) => {
    const file = e.target.files[0];
    if (!file) return;
    const name = file.name.replace(/[^A-Za-z0-9._-]/g, "_") || "deck";
    const path = `/work/load/in/${name}`; // its own folder: never the converted listing's name
    FS.writeFile(path, new Uint8Array(await file.arrayBuffer()));
    job = null;
    // Any deck format in; the keypunch holds its listing (parsons convert reads it).
    const c = parsons(["convert", path, "-o", "/work/load/as-listing.csv"]);
    if (c.code !== 0) {
      showError(c.err);
      return;
    }
    setListing(readText("/work/load/as-listing.csv"));
    e.target.value = "";
  });

  // ---- the generator

  const source = $("gen-source");
  for (const f of FS.readdir("/share/parsons/airfoils").filter((f) => f.endsWith(".dat")).sort()) {
    const o = document.createElement("option");
    o.value = f.replace(/\.dat$/, "");
    o.textContent = `bundled file ${f}`;
    source.appendChild(o);
  }
  source.addEventListener("change", () => { $("gen-naca-label").hidden = source.value !== "naca"; });

  function generate(args) {
    clearFolder("/work/gen");
    const g = parsons(["gen", "airfoil", ...args, "-o", "/work/gen/deck.cbn"]);
    $("gen-output").textContent = g.out;
    if (g.code !== 0) {
      showError(g.err);
      $("gen-output").textContent = g.err;
      return;
    }
    const c = parsons(["convert", "/work/gen/deck.cbn", "-o", "/work/gen/deck.csv"]);
    if (c.code !== 0) {
      showError(c.err);
      return;
    }
    generatedText = readText("/work/gen/deck.csv");
    job = "/work/gen/deck.cbn.job.json";
    setListing(generatedText);
  }

  $("gen-form").addEventListener("submit", (e) => {
    e.preventDefault();
    const from = source.value === "naca" ? ["--naca", $("gen-naca").value.trim()] : ["--dat", source.value];
    generate([...from, "--chord", $("gen-chord").value, "--cutter-radius", $("gen-radius").value,
              "--scallop", $("gen-scallop").value]);
  });

  // ---- the run: parsons runs the punched deck and records it; the viewer plays the record

  window.parsonsTiming = {};
  const signalsCache = { signature: null, signals: null };
  function runDeck() {
    if (!punched && !punchListing()) return false;
    const t0 = performance.now();
    const r = parsons(["run", DECK, "-q", "--report", REPORT, ...(job ? ["--job", job] : [])], true);
    const t1 = performance.now();
    if (r.code !== 0 && r.code !== 3) {
      showError(r.err);
      return false;
    }
    const header = JSON.parse(M.timelineHeader());
    // The signals are the same for every run on one profile: asked for only when they change.
    if (header.signals_signature !== signalsCache.signature) {
      signalsCache.signature = header.signals_signature;
      signalsCache.signals = JSON.parse(M.timelineSignals());
    }
    header.signals = signalsCache.signals;
    const arrays = {
      change_t: M.changeTimes().slice(),
      change_id: M.changeIds().slice(),
      change_v: M.changeValues().slice(),
      motion: M.motion().slice(),
    };
    const report = JSON.parse(readText(REPORT));
    viewer.load(header, arrays, report);
    window.parsonsTiming.runMs = t1 - t0;
    window.parsonsTiming.loadMs = performance.now() - t1;
    ran = true;
    setDownloads();
    return true;
  }
  viewer.beforePlay = () => (ran ? true : runDeck());

  // "To the end": the time from the press to the finished view (tests/js/browser_bench.js).
  $("to-end").addEventListener("click", () => {
    const t0 = performance.now();
    viewer.onFinished = () => {
      window.parsonsTiming.toEndMs = performance.now() - t0;
      viewer.onFinished = null;
    };
  }, true);

  // ---- downloads: what the program would write

  function download(name, data, type) {
    const a = document.createElement("a");
    a.href = URL.createObjectURL(new Blob([data], { type }));
    a.download = name;
    document.body.appendChild(a);
    a.click();
    setTimeout(() => { URL.revokeObjectURL(a.href); a.remove(); }, 1000);
  }
  function setDownloads() {
    $("dl-deck").disabled = !punched;
    $("dl-listing").disabled = !punched;
    $("dl-report").disabled = !punched;
    $("dl-trace").disabled = !punched;
  }
  $("dl-deck").addEventListener("click", () => download("deck.cbn", FS.readFile(DECK), "application/octet-stream"));
  $("dl-listing").addEventListener("click", () => download("deck.csv", listing.value, "text/csv"));
  $("dl-report").addEventListener("click", () => {
    if (ran || runDeck()) download("report.json", FS.readFile(REPORT), "application/json");
  });
  $("dl-trace").addEventListener("click", () => {
    const r = parsons(["run", DECK, "-q", "--trace", "/work/trace.vcd"]);
    if (r.code !== 0 && r.code !== 3) {
      showError(r.err);
      return;
    }
    download("trace.vcd", FS.readFile("/work/trace.vcd"), "text/plain");
  });

  // ---- ready

  for (const id of ["load-sample", "load-demo", "load-file", "gen-go"]) $(id).disabled = false;
  $("load-sample").click();
  // The sample deck is run at once, so that the cabinet stands ready at its first card and the
  // browser has compiled the machine's hot code fully before a visitor's first press.
  runDeck();
  viewer.enable(true);
  status.dataset.state = "ready";
  status.textContent = "The machine is ready: the patent's example deck is in the keypunch. Press Play.";
  window.parsonsReadyAt = performance.now();
})();
