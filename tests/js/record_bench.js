// The recorded run's cost (issue 52, defect 7; docs/web.md): the WebAssembly module run in node
// on a deck, without a record and with the page's record (RunTimeline), median of 21 runs after
// two rounds of warming; printed, not judged (scripts/bench-web.sh).
// Usage: node tests/js/record_bench.js SITE_DIR DECK
'use strict';
const path = require('path');
const fs = require('fs');

const [site, deck] = process.argv.slice(2);
const createParsons = require(path.resolve(site, 'parsons_web.js'));
(async () => {
  const M = await createParsons({ print: () => {}, printErr: () => {}, wasmBinary: fs.readFileSync(path.resolve(site, 'parsons_web.wasm')) });
  M.FS.mkdirTree('/work');
  M.FS.writeFile('/work/deck.cbn', fs.readFileSync(deck));
  const args = JSON.stringify(['run', '/work/deck.cbn', '-q', '--report', '/work/r.json']);
  const median = (record) => {
    const xs = [];
    for (let i = 0; i < 21; i++) {
      const t0 = performance.now();
      M.call(args, record);
      xs.push(performance.now() - t0);
    }
    return xs.sort((a, b) => a - b)[10];
  };
  let plain = 0, recorded = 0;
  for (let round = 0; round < 3; round++) {
    plain = median(false);
    recorded = median(true);
  }
  console.log(`the WebAssembly run in node, median of 21: without a record ${plain.toFixed(2)} ms, ` +
              `recording every change for the page ${recorded.toFixed(2)} ms (${(recorded / plain).toFixed(2)}x)`);
})();
