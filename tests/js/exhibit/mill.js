// The mill, drawn (issue 52, item 1): the machine from above as an SVG that moves with the
// record. At the deck's start it stands at the start; playing, the table slides to the recorded
// table position, the cutter head crosses to the recorded cross position and the cut grows on
// the table; a jump back puts it all back. Its parts carry the patent's numerals. In the live
// page and the --html replay. Run by tests/js/browser_test.js.
'use strict';


function millNow(page) {
  return page.evaluate(() => {
    const svg = document.querySelector('#mill svg.mill');
    if (!svg) return null;
    const v = window.parsonsViewer;
    const cell = (axis) => document.querySelector(`#positions tr[data-axis="${axis}"] td.real`).textContent;
    return {
      t: v.t,
      mi: v.mi,
      table: svg.dataset.table,
      cross: svg.dataset.cross,
      cut: Number(svg.dataset.cutRecords),
      tableCell: cell('table'),
      crossCell: cell('cross'),
      transform: svg.querySelector('.mill-table').getAttribute('transform'),
      labels: [...svg.querySelectorAll('text')].map((e) => e.textContent).join(' | '),
    };
  });
}

async function follows(t, page, where) {
  const { check } = t;
  const say = (v) => JSON.stringify(v);
  const start = await millNow(page);
  check(start && /bed 10/.test(start.labels) && /table 14/.test(start.labels) && /sine plate 16/.test(start.labels) &&
        /upright 18/.test(start.labels) && /crosshead 32/.test(start.labels) && /head 28, cutter 30/.test(start.labels),
        `${where}: the mill is drawn with the patent's numerals`, say(start));
  check(start && start.table === start.tableCell && start.cross === start.crossCell && start.cut <= 1,
        `${where}: at the deck's start the mill stands where the axes start, nothing cut`, say(start));
  await page.evaluate(() => { const v = window.parsonsViewer; v.seek(v.finish * 0.5); });
  const mid = await millNow(page);
  check(mid.table === mid.tableCell && mid.cross === mid.crossCell && mid.cut === mid.mi && mid.cut > 10 &&
        mid.transform !== start.transform,
        `${where}: halfway the table and the head stand at the recorded positions and the cut has grown`, say(mid));
  await page.evaluate(() => window.parsonsViewer.seek(0.16));
  const back = await millNow(page);
  check(back.transform === start.transform && back.cut <= 1 && back.table === back.tableCell,
        `${where}: a jump back puts the table back and takes the cut away`, say(back));
}

module.exports = async function mill(t) {
  const { check } = t;
  const page = await t.open('laptop');
  await follows(t, page, 'live page');
  const inView = await page.evaluate(() => {
    const r = document.querySelector('#mill svg').getBoundingClientRect();
    return r.top >= 0 && r.bottom <= innerHeight && r.width > 300;
  });
  check(inView, 'live page: the mill is in the first view');
  await page.evaluate(() => window.parsonsViewer.seek(0));
  await t.shot(page, 'mill-start');
  await page.evaluate(() => { const v = window.parsonsViewer; v.seek(v.finish * 0.5); });
  await t.shot(page, 'mill-mid');
  await page.close();

  // On the phone: the mill at the top of the machine, mid-cut.
  const phone = await t.open('phone');
  await phone.evaluate(() => { window.parsonsViewer.seek(0); document.getElementById('mill').scrollIntoView(); });
  await t.shot(phone, 'mill-phone-start');
  await phone.evaluate(() => { const v = window.parsonsViewer; v.seek(v.finish * 0.5); document.getElementById('mill').scrollIntoView(); });
  const phoneMill = await millNow(phone);
  check(phoneMill.table === phoneMill.tableCell && phoneMill.cut > 10, 'phone: the mill follows the record', JSON.stringify(phoneMill));
  await t.shot(phone, 'mill-phone');
  await phone.close();

  const replay = await t.openSampleReplay('mill-replay.html');
  await follows(t, replay, '--html replay');
  await replay.close();
};
