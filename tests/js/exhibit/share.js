// Issue 31, item 3 (its share part): the state as a URL. #share puts the deck (by name for the
// built-in decks, else the listing deflated and base64url-encoded) and the machine time into
// the page's address; that address opened in a new page holds the same listing, run, at the
// same instant: machine time, card and positions equal.
'use strict';

// The keypunch may sit in a drawer (a <details>, closed on the first view): opened, as a
// visitor opens it before pressing its buttons.
const openDrawer = (page) => page.evaluate(() => { const d = document.getElementById('deck-drawer'); if (d) d.open = true; });

async function state(page) {
  return page.evaluate(() => ({
    listing: document.getElementById('listing').value,
    seconds: document.getElementById('machine-time').dataset.seconds,
    card: document.getElementById('card-now').textContent,
    positions: document.getElementById('positions').textContent,
  }));
}

async function shareNow(page) {
  // The note of an earlier share is forgotten first: the wait below is for this one.
  await page.evaluate(() => { const n = document.getElementById('share-note'); if (n) delete n.dataset.url; });
  await page.click('#share');
  await page.waitForFunction(() => document.getElementById('share-note') &&
                             document.getElementById('share-note').dataset.url === location.href);
  return page.evaluate(() => location.hash);
}

module.exports = async function share(t) {
  const { check } = t;

  // ---- the sample deck, two cards in
  let page = await t.open('laptop');
  await openDrawer(page);
  await page.click('.speeds [data-speed="100"]');
  for (const expected of ['1 (number 0001)', '2 (number 0002)']) {
    await page.click('#single-card');
    await page.waitForFunction((e) => document.getElementById('card-now').textContent === e &&
                               document.getElementById('run-state').textContent === 'paused', { timeout: 60000 }, expected);
  }
  let hash = await shareNow(page);
  let here = await state(page);
  check(/^#deck=sample&t=\d+(\.\d+)?$/.test(hash) && Number(hash.split('t=')[1]) > 0,
        'Share puts the built-in deck by name and the machine time in the address', hash);
  await t.shot(page, 'share-laptop');
  let there = await t.open('phone', `${hash}`);
  await openDrawer(there);
  let opened = await state(there);
  check(opened.listing === here.listing, 'the shared address opens the same deck');
  check(opened.seconds === here.seconds && opened.card === here.card && opened.positions === here.positions,
        'the shared address opens at the same instant: machine time, card, positions',
        `${here.seconds} s ${here.card} -> ${opened.seconds} s ${opened.card}`);
  await t.shot(there, 'share-opened-phone');
  await there.close();

  // ---- a deck of the visitor's own (one field changed), mid-card: the listing travels in the URL
  const edited = here.listing.replace('1,0,table,+,1,8.785,8.885,8.985,8.985,12', '1,0,table,+,1,8.785,8.885,8.995,8.995,12');
  check(edited !== here.listing, 'the visitor\'s deck differs from the sample');
  await page.$eval('#listing', (e, v) => { e.value = v; e.dispatchEvent(new Event('input')); }, edited);
  await page.waitForFunction(() => /8\.995/.test(document.getElementById('deck-show').textContent));
  await page.click('#play');
  await page.waitForFunction(() => Number(document.getElementById('machine-time').dataset.seconds) > 30, { timeout: 30000 });
  await page.click('#pause');
  hash = await shareNow(page);
  here = await state(page);
  check(/^#deck=z[A-Za-z0-9_-]+&t=\d/.test(hash), 'a deck of the visitor\'s own travels compressed in the address',
        `${hash.length} characters for a listing of ${edited.length}`);
  there = await t.open('laptop', hash);
  await openDrawer(there);
  opened = await state(there);
  check(opened.listing === edited, 'the shared address opens the visitor\'s listing, unchanged');
  check(opened.seconds === here.seconds && opened.card === here.card && opened.positions === here.positions,
        'the visitor\'s deck opens at the same instant', `${here.seconds} s ${here.card} -> ${opened.seconds} s ${opened.card}`);
  await there.close();

  // ---- the demo deck by name
  await page.click('#load-demo');
  await page.waitForFunction(() => document.getElementById('cards').dataset.state === 'drawn' &&
                             document.querySelectorAll('#cards figure').length === 93);
  await page.click('#single-card');
  await page.waitForFunction(() => document.getElementById('run-state').textContent === 'paused', { timeout: 60000 });
  hash = await shareNow(page);
  here = await state(page);
  check(/^#deck=demo&t=/.test(hash), 'the demo deck is shared by name', hash);
  there = await t.open('laptop', hash);
  await openDrawer(there);
  opened = await state(there);
  check(opened.listing === here.listing && opened.seconds === here.seconds && opened.positions === here.positions,
        'the demo deck opens at the same instant', `${here.seconds} -> ${opened.seconds}`);
  await there.close();
  await page.close();
};
