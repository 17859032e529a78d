// Errors in a visitor's words first (issue 52, defect 4): a bad listing cell is named by its
// card and axis, said in plain words and marked in its row; a file that is no deck is said to be
// no deck; parsons' exact words stay one click away (a <details>), the same as the CLI's. Run by
// tests/js/browser_test.js.
'use strict';

const fs = require('fs');
const path = require('path');
const { badCbn: makeBadCbn } = require('../web_support');

const errorOf = (page) => page.evaluate(() => {
  const box = document.getElementById('deck-error');
  const q = (sel) => (box.querySelector(sel) || {}).textContent;
  const details = box.querySelector('details');
  return {
    hidden: box.hidden,
    lead: q('.visitor-words'),
    mark: q('.bad-row mark'),
    row: q('.bad-row'),
    exact: q('.exact'),
    exactOneClickAway: !!details && !details.open,
  };
});

module.exports = async function words(t) {
  const { check, parsons, workDir, SOURCE } = t;
  const say = (v) => JSON.stringify(v);
  const sampleFile = path.join(SOURCE, 'decks', 'samples', 'patent-example.csv');
  const sample = fs.readFileSync(sampleFile, 'utf8');
  const page = await t.open('laptop');
  await page.evaluate(() => { document.getElementById('deck-drawer').open = true; });

  // A listing cell the machine cannot have: speed 9 on card 1's table row.
  const cases = [
    ['1,0,table,+,1,8.785', '1,0,table,+,9,8.785', 'Card 1, table: speed 9: the machine has speeds 1, 2 and 3.', '9'],
    ['2,0,cross,-,2,2.200', '2,0,cross,*,2,2.200', 'Card 2, cross: motion *: an axis moves + (forward) or - (back).', '*'],
    ['3,1,vertical,+,2,2.700,,2.900', '3,1,vertical,+,2,2.700,,2.9', 'Card 3, vertical: stop 2.9: the card holds thousandths, so three decimals, d.ddd.', '2.9'],
  ];
  for (const [from, to, lead, mark] of cases) {
    const bad = sample.replace(from, to);
    check(bad !== sample, `words: the case "${to}" differs from the sample`);
    await page.$eval('#listing', (e, v) => { e.value = v; e.dispatchEvent(new Event('input')); }, bad);
    await page.waitForFunction(() => !document.getElementById('deck-error').hidden);
    const got = await errorOf(page);
    // The sample again before the next case, so that each case's error is its own.
    await page.$eval('#listing', (e, v) => { e.value = v; e.dispatchEvent(new Event('input')); }, sample);
    await page.waitForFunction(() => document.getElementById('deck-error').hidden);
    const file = path.join(workDir, 'words.csv');
    fs.writeFileSync(file, bad);
    const cli = parsons(['show', file]).stderr.trim().split(file).join('listing.csv');
    check(got.lead === lead, `words: "${to}" is said in the visitor's words first`, say(got));
    check(got.mark === mark && got.row.startsWith(to.split(',').slice(0, 3).join(',')),
          `words: "${to}": the bad cell is marked in its row`, say(got));
    check(got.exact === cli && got.exactOneClickAway, `words: "${to}": parsons' exact words one click away`, `${say(got)} CLI ${cli}`);
  }

  // A file that is no deck (a card-start mark inside card 2): said so, then the exact words.
  const badCbn = makeBadCbn(t.parsonsExe, sampleFile, workDir, 'not a deck.cbn');
  await (await page.$('#load-file')).uploadFile(badCbn);
  await page.waitForFunction(() => !document.getElementById('deck-error').hidden);
  const load = await errorOf(page);
  const cliLoad = parsons(['convert', badCbn, '-o', path.join(workDir, 'words-bad.csv')]).stderr.trim().split(badCbn).join('not a deck.cbn');
  check(/^not a deck\.cbn is not a deck parsons can read: card 2 is shorter than a card, or the file is not a deck of punched cards at all/.test(load.lead || ''),
        'words: a damaged deck file is said to be no deck parsons can read', say(load));
  check(load.exact === cliLoad, 'words: its exact words one click away', `${say(load)} CLI ${cliLoad}`);
  await t.shot(page, 'error-words-laptop');
  await page.close();
};
