// The machine view is not an empty box until Play (issue 52, defect 5): on the first view the
// picture from above shows the path the deck takes (faint, from the recorded run) and the cutter
// where it starts, and its legend is in the page's type under it, not a 6-pixel line in the
// canvas. In the live page on a laptop and a phone, and in the --html replay. Run by
// tests/js/browser_test.js.
'use strict';


// Pixels of the picture that are not its background, above the bottom 30 rows (where the old
// page drew its legend), and the legend as the visitor reads it.
function look(page) {
  return page.evaluate(() => {
    const c = document.getElementById('from-above');
    const g = c.getContext('2d');
    const { data } = g.getImageData(0, 0, c.width, c.height - 30);
    let drawn = 0;
    for (let i = 0; i < data.length; i += 4) {
      if (Math.abs(data[i] - 0xf6) + Math.abs(data[i + 1] - 0xf3) + Math.abs(data[i + 2] - 0xea) > 24) drawn++;
    }
    const legend = document.getElementById('from-above-legend');
    const box = legend ? legend.getBoundingClientRect() : null;
    return {
      t: Number(document.getElementById('machine-time').dataset.seconds),
      drawn,
      legend: legend ? legend.textContent : null,
      legendPx: legend ? parseFloat(getComputedStyle(legend).fontSize) : 0,
      legendShown: !!box && box.height > 0,
    };
  });
}

module.exports = async function machineView(t) {
  const { check } = t;
  const say = (v) => JSON.stringify(v);
  for (const screen of ['laptop', 'phone']) {
    const page = await t.open(screen);
    await page.waitForFunction(() => window.parsonsViewer.wholePath !== null);
    const first = await look(page);
    check(first.t === 0 && first.drawn > 800, `${screen}: before Play the picture shows the deck's path, not an empty box`, say(first));
    check(first.legendShown && first.legendPx >= 11 && /the path the deck takes/.test(first.legend) && /cutter now/.test(first.legend),
          `${screen}: the picture's legend is readable type under it`, say(first));
    if (screen === 'laptop') await t.shot(page, 'machine-view-first');
    await page.close();
  }

  // The --html replay opens with the same picture.
  const replay = await t.openSampleReplay('machine-view-replay.html');
  await replay.waitForFunction(() => window.parsonsViewer.wholePath);
  const opened = await look(replay);
  check(opened.drawn > 800 && opened.legendPx >= 11, '--html replay: it opens on the deck\'s path with its legend', say(opened));
  await replay.close();
};
