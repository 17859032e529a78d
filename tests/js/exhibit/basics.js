// The exhibit page's first checks (docs/web.md), run by tests/js/browser_test.js: the sample
// and demo decks run "to the end" in the page end where the native report ends; single card;
// play and pause; field by field; a bad card in the CLI's words; the downloads are the CLI's;
// the generator; `parsons run --html` from disk.
'use strict';

const fs = require('fs');
const path = require('path');
const { watchPage, nativeReport, pageResult, badCbn: makeBadCbn } = require('../web_support');

module.exports = async function basics(t) {
  const { browser, server, site, workDir, parsonsExe, problems, check, parsons, compareRun, SOURCE } = t;
  const page = await browser.newPage();
  await page.setViewport({ width: 1400, height: 1000 });
  watchPage(page, problems);
  // Downloads go to WORK_DIR/downloads under their GUIDs; each is read once chromium says it
  // is complete (Browser.downloadProgress), never while it is being written.
  const downloads = path.join(workDir, 'downloads');
  fs.mkdirSync(downloads, { recursive: true });
  const cdp = await browser.target().createCDPSession();
  await cdp.send('Browser.setDownloadBehavior',
                 { behavior: 'allowAndName', downloadPath: downloads, eventsEnabled: true });
  const finished = new Map(); // guid -> suggested file name, once complete
  const started = new Map();
  cdp.on('Browser.downloadWillBegin', (e) => started.set(e.guid, e.suggestedFilename));
  cdp.on('Browser.downloadProgress', (e) => {
    if (e.state === 'completed') finished.set(e.guid, started.get(e.guid));
  });

  // ---- first view
  await page.goto(`${server.url}/index.html`);
  await page.waitForSelector('body[data-settled="true"]', { timeout: 30000 });
  const readyMs = await page.evaluate(() => window.parsonsReadyAt);
  const wasmBytes = fs.statSync(path.join(site, 'parsons_web.wasm')).size;
  console.log(`first view interactive ${readyMs.toFixed(0)} ms after navigation; ` +
              `parsons_web.wasm ${(wasmBytes / 1048576).toFixed(2)} MiB`);
  check(readyMs > 0, 'the page says when it became interactive');

  // ---- the sample deck, as the page loads it, to the end
  const listing = await page.$eval('#listing', (e) => e.value);
  const sampleFile = path.join(SOURCE, 'decks', 'samples', 'patent-example.csv');
  check(listing === fs.readFileSync(sampleFile, 'utf8'), 'the keypunch holds the sample deck');
  // The cards are figures, each drawn (its <img>) once it scrolls into view (exhibit.js).
  const cards = await page.$$eval('#cards figure', (figs) => figs.length);
  check(cards === 4, 'the sample deck is drawn card by card', `${cards} cards`);
  await page.click('#to-end');
  await page.waitForSelector('#run-state[data-finished="true"]');
  const sample = await pageResult(page);
  compareRun('sample deck', sample, nativeReport(parsonsExe, sampleFile, workDir, 'sample'));
  await page.screenshot({ path: path.join(workDir, 'sample-deck.png'), fullPage: true });

  // ---- the cabinet explains itself
  const hover = await page.$eval('#panel [data-scope="table"] [data-name="speed_switch_236"]',
                                 (e) => e.getAttribute('title'));
  check(/236/.test(hover) && /steps once per impulse/.test(hover), 'speed switch 236 says what it does', hover);
  const dials = await page.$$eval('#panel [data-scope="table"] .dial', (d) => d.map((x) => x.dataset.name));
  check(dials.includes('absolute_counter_110') && dials.includes('increment_counter_316'),
        'the table\'s counters are dials', dials.join(' '));
  // Lamps 270 and 272 light at every stop of the axis: the recorded run lights each of the
  // table's at least once a card.
  const lamps = await page.evaluate(() => {
    const v = window.parsonsViewer;
    const on = {};
    v.h.signals.forEach((s, id) => { if (s && s.scope === 'table' && /^lamp_27[02]$/.test(s.name)) on[id] = [s.name, 0]; });
    for (let i = 0; i < v.a.change_id.length; i++) if (on[v.a.change_id[i]] && v.a.change_v[i] === 1) on[v.a.change_id[i]][1]++;
    return Object.values(on);
  });
  check(lamps.length === 2 && lamps.every(([, n]) => n >= 4), 'lamps 270 and 272 of the table light at its stops',
        JSON.stringify(lamps));

  // ---- single card, at 100x: the first press stops as card 1 is read, the second at card 2
  await page.click('#restart');
  await page.click('.speeds [data-speed="100"]');
  for (const expected of ['1 (number 0001)', '2 (number 0002)']) {
    await page.click('#single-card');
    await page.waitForFunction((e) => document.getElementById('card-now').textContent === e &&
                               document.getElementById('run-state').textContent === 'paused',
                               { timeout: 60000 }, expected);
  }
  check(true, 'single card stops on the next card');
  await page.screenshot({ path: path.join(workDir, 'single-card.png'), fullPage: true });

  // ---- play at 100x for 0.8 s of the wall clock, then pause: about 80 s of machine time
  const seconds = () => page.$eval('#machine-time', (e) => Number(e.dataset.seconds));
  await page.click('#restart');
  await page.click('#play');
  await new Promise((r) => setTimeout(r, 800));
  await page.click('#pause');
  const played = await seconds();
  await new Promise((r) => setTimeout(r, 400));
  const state = await page.$eval('#run-state', (e) => e.textContent);
  check(played > 20 && played < 200 && (await seconds()) === played && state === 'paused',
        'play runs machine time at 100x and pause holds it', `${played} s of machine time, ${state}`);

  // ---- field by field: a cell changed is punched at once. The keypunch is in a drawer, closed
  // on the first view (exhibit/layout.js): open it first.
  await page.click('#deck-drawer > summary');
  await page.waitForFunction(() => document.getElementById('deck-drawer').open);
  await page.click('#tab-fields');
  const cells = await page.$$eval('#fields input', (inputs) => inputs.map((i) => [i.getAttribute('aria-label'), i.value]));
  const stopCell = cells.findIndex(([label, v]) => / stop$/.test(label) && v === '8.985');
  check(stopCell >= 0, 'the fields show card 1\'s table stop', JSON.stringify(cells.slice(0, 12)));
  const edit = async (index, value) => {
    await page.$$eval('#fields input', (inputs, i, v) => {
      inputs[i].value = v;
      inputs[i].dispatchEvent(new Event('change'));
    }, index, value);
  };
  await edit(stopCell, '8.995');
  await edit(stopCell + 1, '8.995'); // its check: the move from 0
  const edited = await page.$eval('#listing', (e) => e.value);
  const shown = await page.$eval('#deck-show', (e) => e.textContent);
  check(edited.includes('1,0,table,+,1,8.785,8.885,8.995,8.995,12') && /8\.995/.test(shown) &&
        (await page.$eval('#deck-error', (e) => e.hidden)),
        'a field changed is in the listing and punched', shown.split('\n').slice(0, 6).join(' | '));
  await page.click('#tab-listing');

  // ---- a bad card: the CLI's own words
  const bad = listing.replace('1,0,table,+,1,8.785', '1,0,table,+,7,8.785');
  check(bad !== listing, 'the bad card differs from the sample');
  await page.$eval('#listing', (e, v) => { e.value = v; e.dispatchEvent(new Event('input')); }, bad);
  await page.waitForSelector('#deck-error:not([hidden])');
  const pageError = await page.$eval('#deck-error .exact', (e) => e.textContent); // one click away
  const badFile = path.join(workDir, 'deck.csv');
  fs.writeFileSync(badFile, bad);
  const cliError = parsons(['show', badFile]).stderr.trim();
  check(pageError === cliError.split(badFile).join('listing.csv'), 'a bad card is worded as the CLI words it',
        `page "${pageError}", CLI "${cliError}"`);
  await page.screenshot({ path: path.join(workDir, 'bad-card.png') });

  // ---- a bad card in a loaded deck file: card and column, in the CLI's words
  const badCbn = makeBadCbn(parsonsExe, sampleFile, workDir, 'bad.cbn');
  const input = await page.$('#load-file');
  await input.uploadFile(badCbn);
  await page.waitForFunction(() => /card 2/.test(document.getElementById('deck-error').textContent));
  const loadError = await page.$eval('#deck-error .exact', (e) => e.textContent);
  const cliLoad = parsons(['convert', badCbn, '-o', path.join(workDir, 'bad.csv')]).stderr.trim();
  check(loadError === cliLoad.split(badCbn).join('bad.cbn') && /column 11/.test(loadError),
        'a bad card in a loaded file is worded as the CLI words it', `page "${loadError}", CLI "${cliLoad}"`);

  // ---- the demo deck: as `parsons demo` generates it, to the end
  await page.click('#load-demo');
  await page.waitForFunction(() => document.getElementById('deck-error').hidden &&
                             document.querySelectorAll('#cards figure').length > 50);
  await page.click('#to-end');
  await page.waitForSelector('#run-state[data-finished="true"]');
  const demo = await pageResult(page);
  const demoDir = path.join(workDir, 'demo');
  const d = parsons(['demo', '--out', demoDir]);
  check(d.status === 0, 'parsons demo runs', d.status === 0 ? '' : d.stderr);
  const demoReport = JSON.parse(fs.readFileSync(path.join(demoDir, 'airfoil-template', 'report.json'), 'utf8'));
  compareRun('demo deck', demo, demoReport);
  const design = await page.evaluate(() => window.parsonsViewer.h.design && window.parsonsViewer.h.design.airfoil);
  check(design === 'naca 2412', 'the demo run draws the cut against the NACA 2412 design', String(design));
  await page.screenshot({ path: path.join(workDir, 'demo-deck.png'), fullPage: true });

  // ---- the downloads are what the CLI writes
  const downloaded = async (button, file) => {
    finished.clear();
    await page.click(button);
    for (let i = 0; i < 200 && finished.size === 0; i++) await new Promise((r) => setTimeout(r, 50));
    const [guid, name] = [...finished.entries()][0] || [];
    if (!guid || name !== file) return null;
    fs.copyFileSync(path.join(downloads, guid), path.join(workDir, file));
    return fs.readFileSync(path.join(workDir, file));
  };
  const deck = await downloaded('#dl-deck', 'deck.cbn');
  const nativeDeck = fs.readFileSync(path.join(demoDir, 'airfoil-template', 'naca2412.cbn'));
  check(deck !== null && deck.equals(nativeDeck), 'the deck download is the deck parsons demo punches',
        deck === null ? 'nothing downloaded' : `${deck.length} bytes against ${nativeDeck.length}`);
  const report = await downloaded('#dl-report', 'report.json');
  const same = (r) => r.machine_seconds === demoReport.machine_seconds && r.status === demoReport.status &&
    JSON.stringify(r.axes) === JSON.stringify(demoReport.axes) && JSON.stringify(r.cards) === JSON.stringify(demoReport.cards);
  check(report !== null && same(JSON.parse(report)), 'the report download is the CLI\'s report of the deck');
  const trace = await downloaded('#dl-trace', 'trace.vcd');
  const nativeTrace = path.join(workDir, 'demo-trace.vcd');
  parsons(['run', path.join(demoDir, 'airfoil-template', 'naca2412.cbn'), '-q', '--trace', nativeTrace]);
  const body = (t) => t.toString().replace(/\$date[\s\S]*?\$end/, '').replace(/\$version[\s\S]*?\$end/, '');
  check(trace !== null && body(trace) === body(fs.readFileSync(nativeTrace)), 'the trace download is the CLI\'s trace');

  // ---- the generator: a bundled coordinate file into the keypunch
  await page.select('#gen-source', 'clarky');
  await page.$eval('#gen-scallop', (e) => { e.value = '0.003'; });
  await page.click('#gen-go');
  await page.waitForFunction(() => /clarky/i.test(document.getElementById('gen-output').textContent) &&
                             document.getElementById('cards').dataset.state === 'drawn');
  const genCards = await page.$$eval('#cards figure', (figs) => figs.length);
  const nativeGen = path.join(workDir, 'clarky.cbn');
  const g = parsons(['gen', 'airfoil', '--dat', 'clarky', '--chord', '6', '--cutter-radius', '0.25',
                     '--scallop', '0.003', '-o', nativeGen, '--json']);
  const nativeCards = JSON.parse(g.stdout).cards;
  check(genCards === Math.min(nativeCards, 200), 'the generator fills the keypunch with the native deck',
        `page ${genCards} cards drawn, CLI ${nativeCards} cards`);
  await page.screenshot({ path: path.join(workDir, 'generator.png'), fullPage: true });
  await page.close();

  // ---- run --html: from disk, no server
  const htmlFile = path.join(workDir, 'sample-replay.html');
  const h = parsons(['run', sampleFile, '-q', '--html', htmlFile]);
  check(h.status === 0 && fs.existsSync(htmlFile), 'parsons run --html writes the page', h.stderr);
  const replay = await browser.newPage();
  await replay.setViewport({ width: 1400, height: 1000 });
  watchPage(replay, problems);
  await replay.goto(`file://${htmlFile}`);
  await replay.click('#to-end');
  await replay.waitForSelector('#run-state[data-finished="true"]');
  compareRun('run --html replay', await pageResult(replay), nativeReport(parsonsExe, sampleFile, workDir, 'replay'));
  await replay.screenshot({ path: path.join(workDir, 'replay.png'), fullPage: true });
  const noScripts = await replay.evaluate(() => [...document.scripts].every((s) => !s.src));
  check(noScripts, 'the --html page loads nothing from outside itself');
};
