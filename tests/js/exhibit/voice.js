// Two voices (issue 52, item 4): one switch above the cabinet turns the engineer's numerals into
// the visitor's plain words on the panel itself, and back. In plain words each axis column says
// what it counts, the numbers its holding relays hold and the move, its speed; the dials and
// banks are labelled by the digit they count or hold. Read from the record: at card 1 of the
// patent's example the table holds 8.785, 8.885 and 8.985 (the patent's own numbers) and the
// move 8.985. In the live page and the --html replay. Run by tests/js/browser_test.js.
'use strict';

const panelWords = (page) => page.evaluate(() => ({
  voice: document.body.dataset.voice,
  pressed: document.getElementById('voice').getAttribute('aria-pressed'),
  table: (document.querySelector('#panel [data-scope="table"] .plain-line') || {}).textContent || '',
  shown: !!document.querySelector('#panel [data-scope="table"] .plain-line') &&
    getComputedStyle(document.querySelector('#panel [data-scope="table"] .plain-line')).display !== 'none',
  shared: (document.querySelector('#panel [data-scope="cabinet"] .plain-line') || {}).textContent || '',
  dial110: document.querySelector('#panel [data-scope="table"] [data-name="absolute_counter_110"] .label').textContent,
  bank352: document.querySelector('#panel [data-scope="table"] [data-bank="absolute_storage_352"] .label').textContent,
}));

async function twoVoices(t, page, where) {
  const { check } = t;
  const say = (v) => JSON.stringify(v);
  // After card 1's holding relays have picked, before the table has moved far.
  await page.evaluate(() => window.parsonsViewer.seek(0.2));
  const engineer = await panelWords(page);
  check(engineer.voice === 'engineer' && !engineer.shown && engineer.dial110 === '110' && engineer.bank352 === '352',
        `${where}: the engineer's voice by default: numerals, no plain lines`, say(engineer));
  await page.click('#voice');
  const visitor = await panelWords(page);
  check(visitor.voice === 'visitor' && visitor.pressed === 'true' && visitor.shown &&
        /holds the numbers 8\.785, 8\.885, 8\.985/.test(visitor.table) && /the move 8\.985 in/.test(visitor.table) &&
        /^counts \d\.\d{3} in/.test(visitor.table) && /card 1 in the reader/.test(visitor.shared) &&
        visitor.dial110 === 'thou.' && visitor.bank352 === 'tenth',
        `${where}: plain words on the panel: what the table counts and holds, the digits' places`, say(visitor));
  await page.evaluate(() => { const v = window.parsonsViewer; v.seek(v.finish); });
  const end = await panelWords(page);
  check(end.table !== visitor.table && /^counts 0\.100 in/.test(end.table), `${where}: the plain words follow the instant shown`, say(end));
  await page.click('#voice');
  const back = await panelWords(page);
  check(back.voice === 'engineer' && !back.shown && back.dial110 === '110', `${where}: the switch gives the numerals back`, say(back));
}

module.exports = async function voice(t) {
  const page = await t.open('laptop');
  await twoVoices(t, page, 'live page');
  await page.click('#voice');
  await page.evaluate(() => window.parsonsViewer.seek(0.2));
  await t.shot(page, 'voice-plain-laptop');
  await page.close();
  const replay = await t.openSampleReplay('voice-replay.html');
  await twoVoices(t, replay, '--html replay');
  await replay.close();
};
