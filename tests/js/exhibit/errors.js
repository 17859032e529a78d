// Issue 31, item 4 (the page's part): errors where the eye is. One clean line, no progress text
// after a generation; in field-by-field mode the message under the bad cell, the cell marked
// aria-invalid (and visibly), the card pictures kept, Play saying why it does not run; a failed
// load stops Play on the old deck; no message names the page's internal /work/ files.
'use strict';

// The keypunch may sit in a drawer (a <details>, closed on the first view): opened, as a
// visitor opens it before pressing its buttons.
const openDrawer = (page) => page.evaluate(() => { const d = document.getElementById('deck-drawer'); if (d) d.open = true; });

const path = require('path');
const { badCbn: makeBadCbn } = require('../web_support');

const MESSAGES = ['#deck-error', '#stop-message', '#gen-output', '#fields tr.field-error', '#deck-show', '#run-state'];
async function messages(page) {
  return page.evaluate((sel) => sel.map((s) => [...document.querySelectorAll(s)].map((e) => e.textContent).join('\n')), MESSAGES);
}

module.exports = async function errors(t) {
  const { check, parsons, workDir, SOURCE } = t;
  const seen = [];
  const sampleFile = path.join(SOURCE, 'decks', 'samples', 'patent-example.csv');

  // ---- after a generation, a generator error is one clean line: the CLI's, nothing before it
  let page = await t.open('laptop');
  await openDrawer(page);
  await page.click('#load-demo');
  await page.waitForFunction(() => /cards\s+93/.test(document.getElementById('gen-output').textContent));
  const summary = await page.$eval('#gen-output', (e) => e.textContent);
  check(!/\r|\[#|%/.test(summary) && /wrote\s+gen\/deck\.cbn/.test(summary),
        'the generator\'s summary is clean (no progress line) and names its deck without /work/', JSON.stringify(summary));
  await page.$eval('#gen-chord', (e) => { e.value = '60'; }); // wider than the counters reach
  await page.click('#gen-go');
  await page.waitForSelector('#deck-error:not([hidden])');
  const genError = await page.$eval('#deck-error .exact', (e) => e.textContent);
  const cliGen = parsons(['gen', 'airfoil', '--naca', '2412', '--chord', '60', '--cutter-radius', '0.25', '--scallop', '0.005',
                          '-o', path.join(workDir, 'x.cbn')]).stderr.trim();
  check(genError === cliGen && !genError.includes('\r') && genError.split('\n').length === 1,
        'a generator error after a generation is one clean line, the CLI\'s', JSON.stringify(genError));
  seen.push(...await messages(page));
  await page.close();

  // ---- field by field: the bad cell, its message beside it, on a laptop and a phone
  for (const screen of ['laptop', 'phone']) {
    page = await t.open(screen);
    await openDrawer(page);
    await page.click('#tab-fields');
    const figsBefore = await page.$$eval('#cards figure', (f) => f.length);
    const speed = await page.evaluate(() => [...document.querySelectorAll('#fields input')]
      .findIndex((x) => / speed$/.test(x.getAttribute('aria-label'))));
    await page.evaluate((i) => {
      const input = document.querySelectorAll('#fields input')[i];
      input.value = '7';
      input.dispatchEvent(new Event('change', { bubbles: true }));
    }, speed);
    await page.waitForSelector('#fields tr.field-error');
    const where = await page.evaluate((i) => {
      const cell = document.querySelectorAll('#fields input')[i];
      cell.scrollIntoView({ block: 'center' });
      const c = cell.getBoundingClientRect();
      const m = document.querySelector('#fields tr.field-error').getBoundingClientRect();
      // The words themselves, within the screen's width (a table scrolled sideways on a phone).
      const w = (document.querySelector('#fields tr.field-error td > div') || document.querySelector('#fields tr.field-error')).getBoundingClientRect();
      const invalid = [...document.querySelectorAll('#fields [aria-invalid="true"]')];
      const style = getComputedStyle(cell);
      return { gap: m.top - c.bottom, inView: m.top >= 0 && m.bottom <= innerHeight && w.left >= -1 && w.right <= innerWidth + 1, invalid: invalid.length,
               isCell: invalid[0] === cell, outline: style.outlineStyle, text: document.querySelector('#fields tr.field-error').textContent,
               described: cell.getAttribute('aria-describedby') };
    }, speed);
    check(where.isCell && where.invalid === 1 && where.outline !== 'none' && where.described === 'field-error',
          `${screen}: the bad cell, and only it, is aria-invalid and visibly marked`, JSON.stringify(where));
    check(where.gap >= -2 && where.gap < 80 && where.inView && /listing\.csv:15: speed '7'/.test(where.text),
          `${screen}: the message stands right under the bad cell, in view`, `${where.gap.toFixed(0)} px below it: ${where.text}`);
    await t.shot(page, `error-field-${screen}`);
    // A card's picture is made when it scrolls into view (an IntersectionObserver, whose callback
    // a loaded machine may run late): bring the cards into view and give it the time to.
    await page.evaluate(() => document.querySelector('#cards').scrollIntoView({ block: 'start' }));
    await page.waitForFunction(() => document.querySelectorAll('#cards figure img').length > 0, { timeout: 10000 })
      .catch(() => {});
    const figsAfter = await page.$$eval('#cards figure', (f) => f.length);
    const imgs = await page.$$eval('#cards figure img', (f) => f.length);
    check(figsAfter === figsBefore && figsAfter === 4 && imgs > 0, `${screen}: the card pictures stay under a bad cell`,
          `${figsBefore} -> ${figsAfter} figures, ${imgs} pictures`);
    // Play on the bad deck: stopped, saying why beside Play; machine time does not move.
    const t0 = await page.$eval('#machine-time', (e) => e.dataset.seconds);
    await page.$eval('#play', (b) => b.scrollIntoView({ block: 'center', inline: 'center' }));
    await page.click('#play');
    await new Promise((r) => setTimeout(r, 600));
    const play = await page.evaluate(() => ({
      t: document.getElementById('machine-time').dataset.seconds,
      state: document.getElementById('run-state').textContent,
      msg: document.getElementById('stop-message').hidden ? '' : document.getElementById('stop-message').textContent,
    }));
    check(play.t === t0 && /error/.test(play.state) && /^Cannot run: Card 1, table: speed 7: the machine has speeds 1, 2 and 3/.test(play.msg),
          `${screen}: Play on a bad deck does not run and says why beside Play`, JSON.stringify(play));
    await page.$eval('#play', (b) => b.scrollIntoView({ block: 'center' }));
    await t.shot(page, `error-play-${screen}`);
    // The cell mended: the mark and the message go.
    await page.evaluate((i) => {
      const input = document.querySelectorAll('#fields input')[i];
      input.value = '1';
      input.dispatchEvent(new Event('change', { bubbles: true }));
    }, speed);
    const mended = await page.evaluate(() => [document.querySelectorAll('#fields [aria-invalid="true"], #fields tr.field-error').length,
                                              document.getElementById('stop-message').hidden]);
    check(mended[0] === 0 && mended[1], `${screen}: the cell mended, mark and messages go`, JSON.stringify(mended));
    seen.push(...await messages(page));
    await page.close();
  }

  // ---- a failed load while the old deck plays: Play stops, the old deck is kept and says so
  page = await t.open('laptop');
  await openDrawer(page);
  const badCbn = makeBadCbn(t.parsonsExe, sampleFile, workDir, 'my bad deck.cbn');
  await page.click('.speeds [data-speed="100"]');
  await page.click('#play');
  await page.waitForFunction(() => Number(document.getElementById('machine-time').dataset.seconds) > 5);
  const listingBefore = await page.$eval('#listing', (e) => e.value);
  await (await page.$('#load-file')).uploadFile(badCbn);
  await page.waitForSelector('#deck-error:not([hidden])');
  const tA = await page.$eval('#machine-time', (e) => e.dataset.seconds);
  await new Promise((r) => setTimeout(r, 600));
  const after = await page.evaluate(() => ({
    t: document.getElementById('machine-time').dataset.seconds,
    state: document.getElementById('run-state').textContent,
    msg: document.getElementById('stop-message').hidden ? '' : document.getElementById('stop-message').textContent,
    err: document.querySelector('#deck-error .exact').textContent,
    listing: document.getElementById('listing').value,
  }));
  check(after.t === tA && /load failed/.test(after.state) && /^Not loaded: my bad deck\.cbn is not a deck parsons can read: card 2 .*kept the previous deck/.test(after.msg),
        'a failed load stops Play on the old deck and says why beside Play', JSON.stringify({ ...after, listing: undefined }));
  check(after.listing === listingBefore, 'the keypunch keeps the old deck after a failed load');
  const cliLoad = parsons(['convert', badCbn, '-o', path.join(workDir, 'err-bad.csv')]).stderr.trim();
  check(after.err === cliLoad.split(badCbn).join('my bad deck.cbn'),
        'the failed load names the file as the visitor chose it (spaces and all), in the CLI\'s words', `page "${after.err}"`);
  await t.shot(page, 'error-load-laptop');
  // Play again: the kept deck runs, the load error is done with.
  await page.click('#play');
  await page.waitForFunction((a) => Number(document.getElementById('machine-time').dataset.seconds) > Number(a) ||
                             document.getElementById('run-state').textContent === 'running', {}, tA);
  const cleared = await page.evaluate(() => [document.getElementById('deck-error').hidden, document.getElementById('stop-message').hidden]);
  check(cleared[0] && cleared[1], 'Play pressed again runs the kept deck and the load error goes', JSON.stringify(cleared));
  await page.click('#pause');
  seen.push(...await messages(page));
  await page.close();

  const internal = seen.filter((m) => m.includes('/work/'));
  check(internal.length === 0 && seen.some((m) => /listing\.csv/.test(m)), 'no message of the page names /work/ (the page\'s internal files)',
        internal.join(' | '));
};
