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
  // For the console and the tests: parsonsCall(["show", "listing.csv"]) (in /work).
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
  // parsons runs in /work and is given names relative to it, so that what it prints names the
  // deck as the visitor knows it (listing.csv, the loaded file's own name), never /work/...
  FS.chdir("/work");

  const LISTING = "listing.csv";
  const DECK = "deck.cbn";
  const REPORT = "report.json";
  const MOST_DRAWN_ROWS = 5000; // about 1000 cards
  const listing = $("listing");
  const deckError = $("deck-error");
  let punched = false;   // deck.cbn holds the listing's cards
  let ran = false;       // the viewer holds the run of those cards
  let job = null;        // the job description of a generated deck, while its listing is untouched
  let generatedText = null;
  let deckName = null;   // "sample" or "demo" while the keypunch holds that built-in deck untouched
  let loadedText = null; // the listing as it was loaded (deckName holds while it is unchanged)

  // parsons' messages, clean: the progress line it draws on a terminal (\r, then the next
  // state) is dropped, so that only what parsons said in words stays, one line each.
  const clean = (text) => text.split("\n").map((l) => l.split("\r").pop().trimEnd())
    .filter((l) => l.trim() !== "").join("\n");

  // The error in the keypunch, and, while the deck cannot run, beside Play too: Play is stopped
  // and says why instead of doing nothing (or playing the previous deck under a red error).
  // failedLoad: a file or a generation that did not come in; the keypunch keeps its deck.
  let currentError = "";
  function showError(text, failedLoad = false) {
    text = text ? clean(text) : "";
    currentError = text;
    deckError.hidden = !text;
    deckError.textContent = "";
    if (text) deckError.append(...explained(text));
    markField(text);
    if (text) stopForError(text, failedLoad);
    else clearStopForError();
  }
  // The top line says what the machine is doing (issue 52, defect 3): a deck that cannot run or
  // a load that failed, else the run at the instant shown, the tour's stop included, as the
  // viewer tells it (web/viewer.js statusWords).
  let errorWords = null;
  function sayStatus() {
    const [state, text] = errorWords || viewer.statusWords();
    status.dataset.state = state;
    status.textContent = text;
  }
  // A deck error in a visitor's words, parsons' exact words one click away (web/words.js).
  const explained = (text, withRow = true) =>
    ParsonsWords.explained(document, text, { listingName: LISTING, listingText: listing.value, withRow });
  let stoppedForError = false;
  function stopForError(text, failedLoad) {
    viewer.pause();
    notRun(); // Play runs what the keypunch holds now, never silently the previous record
    stoppedForError = true;
    const msg = $("stop-message");
    msg.hidden = false;
    msg.dataset.deckError = "true";
    const lead = explained(text)[0].textContent; // the visitor's words; the exact ones in the keypunch
    msg.textContent = failedLoad ? `Not loaded: ${lead} The keypunch kept the previous deck: Play runs it.`
      : `Cannot run: ${lead}`;
    const state = $("run-state");
    state.textContent = failedLoad ? "stopped: the load failed" : "stopped: the deck has an error";
    state.dataset.reason = "deck-error";
    errorWords = failedLoad
      ? ["load-failed", "That file did not load: the reason is under the controls. The keypunch kept its deck, and Play runs it."]
      : ["deck-error", "This deck cannot run: a card has an error, marked in the keypunch. Mend it and press Play."];
    sayStatus();
  }
  function clearStopForError() {
    if (!stoppedForError) return;
    stoppedForError = false;
    errorWords = null;
    sayStatus();
    const msg = $("stop-message");
    if (msg.dataset.deckError) { msg.hidden = true; msg.textContent = ""; delete msg.dataset.deckError; }
    const state = $("run-state");
    if (state.dataset.reason === "deck-error") { state.textContent = "not run"; state.dataset.reason = ""; }
  }

  // ---- the keypunch: every change is punched and drawn at once

  // now: the pictures at once (the first view), not in the task after the next frame.
  function punchListing(fromField = false, now = false) {
    FS.writeFile(LISTING, listing.value);
    punched = false;
    notRun();
    setDownloads();
    const shown = parsons(["show", LISTING]);
    $("deck-show").textContent = shown.out;
    if (shown.code !== 0) {
      // The cards of the last good listing stay, marked as not what the listing says now.
      pictureToken++;
      $("cards").classList.add("stale");
      $("cards").dataset.state = "stale";
      showError(shown.err);
      return false;
    }
    $("cards").classList.remove("stale");
    const p = parsons(["punch", LISTING, "-o", DECK]);
    if (p.code !== 0) {
      showError(p.err);
      return false;
    }
    showError("");
    punched = true;
    if (job && listing.value !== generatedText) job = null; // edited: no longer the generated deck
    setDownloads();
    // A cell edited keeps its table (and the visitor's place in it); a new listing rebuilds it.
    if ($("fields").hidden === false && !fromField) buildFields();
    runSoon();
    if (now) drawPictures(listing.value);
    else {
      // The pictures (parsons show --svg, ~1,000 <text> a card) in a task of their own after the
      // next frame: the page answers the press first. A newer punch supersedes this one.
      const token = ++pictureToken;
      const text = listing.value;
      $("cards").dataset.state = "drawing";
      requestAnimationFrame(() => setTimeout(() => { if (token === pictureToken) drawPictures(text); }, 0));
    }
    return true;
  }
  let pictureToken = 0;
  function drawPictures(text) {
    FS.writeFile(LISTING, text);
    clearFolder("/work/cards");
    // A long deck is shown but not drawn: a picture a card would fill the page's memory.
    const rows = text.split("\n").filter((l) => l.trim() && !l.trimStart().startsWith("#")).length;
    const draw = rows <= MOST_DRAWN_ROWS;
    if (draw) parsons(["show", LISTING, "--svg", "cards"]);
    drawCards(draw);
    $("cards").dataset.state = "drawn";
  }

  // The card pictures: a figure per card at once (cheap), its picture made only when it scrolls
  // into view; a card whose picture did not change keeps its figure (one field edited redraws
  // one card). The pictures stay in the in-memory files until the next punch.
  const shownSvg = new Map(); // card file -> its SVG text, as drawn or to be drawn
  const cardsSeen = new IntersectionObserver((entries) => {
    for (const e of entries) if (e.isIntersecting) { cardsSeen.unobserve(e.target); drawCard(e.target); }
  }, { rootMargin: "200px" });
  function drawCard(fig) {
    const svg = shownSvg.get(fig.dataset.file);
    if (svg === undefined) return;
    let img = fig.querySelector("img");
    if (!img) {
      img = document.createElement("img");
      img.alt = `card ${fig.dataset.file.replace(/\D/g, "").replace(/^0+/, "")} as punched`;
      fig.prepend(img);
    } else URL.revokeObjectURL(img.src);
    img.src = URL.createObjectURL(new Blob([svg], { type: "image/svg+xml" }));
    fig.dataset.drawn = "true";
  }
  function dropCard(fig) {
    cardsSeen.unobserve(fig);
    const img = fig.querySelector("img");
    if (img) URL.revokeObjectURL(img.src);
    shownSvg.delete(fig.dataset.file);
    fig.remove();
  }
  function drawCards(draw) {
    const box = $("cards");
    const note = box.querySelector("p.more");
    if (note) note.remove();
    if (!draw) {
      for (const fig of [...box.querySelectorAll("figure")]) dropCard(fig);
      box.textContent = `A deck this long is not drawn here (more than ${MOST_DRAWN_ROWS} rows); ` +
        "parsons show --svg draws every card.";
      return;
    }
    if (!box.querySelector("figure")) box.textContent = "";
    const files = FS.readdir("/work/cards").filter((f) => f.endsWith(".svg")).sort();
    const wanted = new Set(files.slice(0, 200));
    for (const fig of [...box.querySelectorAll("figure")]) if (!wanted.has(fig.dataset.file)) dropCard(fig);
    let before = box.firstElementChild;
    for (const f of wanted) {
      const svg = readText(`/work/cards/${f}`);
      let fig = box.querySelector(`figure[data-file="${f}"]`);
      if (!fig) {
        fig = document.createElement("figure");
        fig.dataset.file = f;
        const cap = document.createElement("figcaption");
        cap.textContent = f.replace(".svg", "");
        fig.append(cap);
        box.insertBefore(fig, before);
      } else before = fig.nextElementSibling;
      if (shownSvg.get(f) === svg) continue;
      shownSvg.set(f, svg);
      if (fig.dataset.drawn) drawCard(fig); // in view already: its new picture now
      else cardsSeen.observe(fig);
    }
    if (files.length > 200) {
      const more = document.createElement("p");
      more.className = "more";
      more.textContent = `… and ${files.length - 200} more cards (download the deck to see them all).`;
      box.appendChild(more);
    }
  }

  let typing = null;
  listing.addEventListener("input", () => {
    clearTimeout(typing);
    typing = setTimeout(punchListing, 250);
  });

  function setListing(text, name = null, now = false) {
    listing.value = text;
    deckName = name;
    loadedText = text;
    punchListing(false, now);
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
      tr.dataset.line = String(n);
      cells.forEach((c, i) => {
        const td = tr.insertCell();
        const input = document.createElement("input");
        input.value = c;
        input.setAttribute("aria-label", `line ${n + 1} ${header[i] || ""}`);
        input.dataset.line = String(n);
        input.dataset.cell = String(i);
        input.dataset.column = header[i] || "";
        input.addEventListener("change", () => {
          const all = listing.value.split("\n");
          const row = all[n].split(",");
          row[i] = input.value;
          all[n] = row.join(",");
          listing.value = all.join("\n");
          punchListing(true);
        });
        td.appendChild(input);
      });
    });
    box.appendChild(table);
    markField(currentError);
  }

  // In field-by-field mode the error stands under the row of the bad cell, the cell marked
  // aria-invalid: parsons names the line (listing.csv:15:) and the field or its value.
  function markField(text) {
    const box = $("fields");
    for (const bad of box.querySelectorAll('[aria-invalid="true"]')) bad.removeAttribute("aria-invalid");
    for (const old of box.querySelectorAll("tr.field-error")) old.remove();
    const m = text && text.match(new RegExp(`${LISTING.replace(".", "\\.")}:(\\d+):\\s*(.*)`));
    if (!m) return;
    const tr = box.querySelector(`tr[data-line="${Number(m[1]) - 1}"]`);
    if (!tr) return;
    const inputs = [...tr.querySelectorAll("input")];
    const said = m[2].toLowerCase();
    const quoted = (said.match(/'([^']*)'/) || [])[1];
    const cell = inputs.find((i) => i.dataset.column && new RegExp(`\\b${i.dataset.column.toLowerCase()}\\b`).test(said)) ||
      inputs.find((i) => quoted !== undefined && i.value.trim() === quoted) || inputs[0];
    cell.setAttribute("aria-invalid", "true");
    const row = tr.parentNode.insertRow(tr.rowIndex + 1);
    row.className = "field-error";
    const td = row.insertCell();
    td.colSpan = inputs.length;
    td.id = "field-error";
    td.setAttribute("role", "alert");
    // The words in a block that stays at the visible left of a table scrolled sideways (phone).
    const words = document.createElement("div");
    words.append(...explained(text, false));
    td.append(words);
    if (!box.hidden) deckError.hidden = true; // said under the cell itself: not twice
    cell.setAttribute("aria-describedby", "field-error");
  }
  function tab(which) {
    $("tab-listing").setAttribute("aria-selected", String(which === "listing"));
    $("tab-fields").setAttribute("aria-selected", String(which === "fields"));
    listing.hidden = which !== "listing";
    $("fields").hidden = which !== "fields";
    deckError.hidden = !currentError;
    if (which === "fields") buildFields();
  }
  $("tab-listing").addEventListener("click", () => tab("listing"));
  $("tab-fields").addEventListener("click", () => tab("fields"));

  // ---- decks in: the samples, the demo deck, a file

  const SAMPLE = "/share/parsons/samples/patent-example.csv";
  function loadSample(now = false) {
    job = null;
    setListing(readText(SAMPLE), "sample", now === true);
  }
  $("load-sample").addEventListener("click", loadSample);

  // The deck `parsons demo` generates and runs: NACA 2412, 6 in chord, cutter radius 0.25 in,
  // scallop 0.002 in.
  const DEMO = ["--naca", "2412", "--chord", "6", "--cutter-radius", "0.25", "--scallop", "0.002"];
  const loadDemo = () => generate(DEMO, "demo");
  $("load-demo").addEventListener("click", loadDemo);

  $("load-file").addEventListener("change", async (e) => {
    const file = e.target.files[0];
    if (!file) return;
    // Its own folder, under its own name (a file name never holds "/"): parsons' messages
    // name it as the visitor chose it.
    const name = file.name.replace(/\//g, "_") || "deck";
    clearFolder("/work/load/in");
    FS.writeFile(`/work/load/in/${name}`, new Uint8Array(await file.arrayBuffer()));
    e.target.value = "";
    // Any deck format in; the keypunch holds its listing (parsons convert reads it).
    FS.chdir("/work/load/in");
    const c = parsons(["convert", name, "-o", "../as-listing.csv"]);
    FS.chdir("/work");
    if (c.code !== 0) {
      // The keypunch keeps the previous deck; Play is stopped until the visitor presses it again.
      showError(c.err, true);
      return;
    }
    job = null;
    setListing(readText("/work/load/as-listing.csv"), null);
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

  function generate(args, name = null) {
    clearFolder("/work/gen");
    const g = parsons(["gen", "airfoil", ...args, "-o", "gen/deck.cbn"]);
    if (g.code !== 0) {
      $("gen-output").textContent = "";
      showError(g.err, true);
      return;
    }
    // The summary parsons printed, without the progress line it drew on the way.
    $("gen-output").textContent = clean(g.out);
    const c = parsons(["convert", "gen/deck.cbn", "-o", "gen/deck.csv"]);
    if (c.code !== 0) {
      showError(c.err);
      return;
    }
    generatedText = readText("/work/gen/deck.csv");
    job = "gen/deck.cbn.job.json";
    setListing(generatedText, name);
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
  // The viewer no longer holds the run of the keypunch's deck; a run planned is called off.
  function notRun() {
    ran = false;
    runToken++;
    $("run-state").dataset.ran = "false";
  }
  // The deck just punched is run in a task after the next frame, behind its card pictures, so
  // that the cabinet stands at its first card and Play, One card and To the end start at once
  // (docs/web.md). Not while the viewer plays or the tour is open (the visitor is watching the
  // record they show): then the next press runs it, as it does when pressed before this task.
  let runToken = 0;
  function runSoon() {
    const token = ++runToken;
    requestAnimationFrame(() => setTimeout(() => {
      if (token !== runToken || ran || !punched || viewer.playing || !$("tour").hidden) return;
      runDeck(false);
    }, 0));
  }
  // pressed: a press is waiting for this run (the timing says whether the press ran the deck).
  function runDeck(pressed = true) {
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
    // Play pressed after a failed load runs the deck the keypunch kept: the error is done with.
    showError("");
    viewer.load(header, arrays, report);
    window.parsonsTiming.runMs = t1 - t0;
    window.parsonsTiming.loadMs = performance.now() - t1;
    window.parsonsTiming.runOnPress = pressed;
    ran = true;
    $("run-state").dataset.ran = "true";
    setDownloads();
    return true;
  }
  viewer.beforePlay = () => (ran ? true : runDeck());

  // After the tour: punch your own card (web/guide.js): the visitor's move as G-code, made
  // into cards by `parsons gen gcode`, run and played at 10x.
  if (viewer.tour && typeof ParsonsGuide !== "undefined") {
    ParsonsGuide.install(document, viewer.tour, (program) => {
      clearFolder("/work/gen");
      FS.writeFile("/work/gen/your-card.ngc", program);
      const g = parsons(["gen", "gcode", "gen/your-card.ngc", "--to", "listing", "-o", "gen/your-card.csv"]);
      if (g.code !== 0) {
        showError(g.err, true); // in the keypunch's words; the keypunch keeps its deck
        return;
      }
      job = null;
      setListing(readText("/work/gen/your-card.csv"), null, true);
      if (!punched || !runDeck()) return;
      viewer.chooseSpeed("10");
      viewer.play();
    });
  }

  // ---- the state as a URL: the deck and the instant (#deck=sample&t=12.5)
  // A built-in deck by its name; any other listing deflated (CompressionStream, in the browser)
  // and base64url-encoded, "z" in front; t the machine time in seconds.

  const b64url = (bytes) => {
    let bin = "";
    for (let i = 0; i < bytes.length; i += 0x8000) bin += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
    return btoa(bin).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
  };
  const unb64url = (text) => Uint8Array.from(atob(text.replace(/-/g, "+").replace(/_/g, "/")), (c) => c.charCodeAt(0));
  async function through(bytes, stream) {
    return new Uint8Array(await new Response(new Blob([bytes]).stream().pipeThrough(stream)).arrayBuffer());
  }
  async function shareHash() {
    const deck = deckName && listing.value === loadedText ? deckName
      : "z" + b64url(await through(new TextEncoder().encode(listing.value), new CompressionStream("deflate-raw")));
    const t = viewer.loaded && ran ? viewer.t : 0;
    return `#deck=${deck}&t=${t}`;
  }
  $("share").addEventListener("click", async () => {
    if (!ran && !runDeck()) return;
    const hash = await shareHash();
    history.replaceState(null, "", hash);
    const url = location.href;
    let note = $("share-note");
    if (!note) {
      note = document.createElement("p");
      note.id = "share-note";
      note.className = "note";
      note.setAttribute("aria-live", "polite");
      $("share").closest(".controls").after(note);
    }
    let copied = false;
    try { await navigator.clipboard.writeText(url); copied = true; } catch (e) { /* not allowed here: shown below */ }
    note.textContent = `${copied ? "Copied" : "This instant"}: `;
    const a = document.createElement("a");
    a.href = url;
    a.textContent = url.length > 120 ? `${url.slice(0, 117)}…` : url;
    note.append(a);
    note.dataset.url = url;
  });

  // Opened with such a hash: that deck, run, the viewer at that instant. false when the hash
  // names no deck (the page then starts as always).
  async function openShared() {
    const q = new URLSearchParams(location.hash.slice(1));
    const deck = q.get("deck");
    if (!deck) return false;
    if (deck === "sample") loadSample();
    else if (deck === "demo") loadDemo();
    else if (deck.startsWith("z")) {
      let text;
      try {
        text = new TextDecoder().decode(await through(unb64url(deck.slice(1)), new DecompressionStream("deflate-raw")));
      } catch (e) {
        showError("This link's deck could not be read (it was cut short?); the sample deck is in the keypunch.");
        loadSample();
        return true;
      }
      job = null;
      setListing(text, null);
    } else return false;
    if (!runDeck(false)) return true;
    const t = Math.min(Math.max(Number(q.get("t")) || 0, 0), viewer.finish);
    if (typeof viewer.seek === "function") viewer.seek(t);
    else { viewer.reset(false); viewer.advanceTo(t); }
    return true;
  }

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
    const r = parsons(["run", DECK, "-q", "--trace", "trace.vcd"]);
    if (r.code !== 0 && r.code !== 3) {
      showError(r.err);
      return;
    }
    download("trace.vcd", FS.readFile("trace.vcd"), "text/plain");
  });

  // ---- ready

  for (const id of ["load-sample", "load-demo", "load-file", "gen-go"]) $(id).disabled = false;
  const shared = await openShared();
  if (!shared) loadSample();
  viewer.enable(true);
  $("share").disabled = false;
  viewer.onState = sayStatus;
  sayStatus();
  window.parsonsReadyAt = performance.now();
  // The sample deck is run once the page has answered (runSoon, after the next frame, behind
  // its card pictures), so that the cabinet stands at its first card and the browser has
  // compiled the machine's hot code before a visitor's first press; a press before that runs it
  // itself. body[data-settled] says the first view is whole (the tests wait for it).
  const settle = () => {
    if (!ran) runDeck(false);
    window.parsonsSettledAt = performance.now();
    document.body.dataset.settled = "true";
  };
  if (shared) settle();
  else requestAnimationFrame(() => setTimeout(settle, 0));
})();
