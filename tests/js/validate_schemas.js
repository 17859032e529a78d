#!/usr/bin/env node
// Validates every JSON file parsons writes against the JSON Schemas of docs/schemas/ (draft
// 2020-12, Ajv): the run report, every line of the events stream, the saved state, the machine
// profile, the --json documents of show, check, gen and punch, and the job files of gen.
//
//   node tests/js/validate_schemas.js PARSONS_EXE WORK_DIR
//
// It runs the executable (no shell) over real commands in WORK_DIR so that every output kind and
// every branch of the schemas appears: the sample deck run through and stopped once by each
// check it can be made to fire, condition, sync and tap cards under parsons-extended, every gen
// subcommand and the proofs of what it generated, show/check/punch/gen --json, and the profile
// of each built-in name. Then it checks:
//   - every file (and every line of every events file) against its schema: one line per file,
//     and on a failure the file, the JSON pointer and Ajv's message;
//   - coverage: every event kind and stop reason of the schemas' enums was seen (but the stop
//     reasons listed in NOT_PROVOKED, with why), and every branch the schemas describe (the
//     commands, generators, card kinds, finding kinds, job kinds, report blocks, ...);
//   - that the schemas are strict: a valid report with a required key deleted, an unknown key
//     added or a number turned into a string must fail (and a few more such mutations).
// Exit 0 when all holds, 1 otherwise. WORK_DIR is left as it is for inspection; it is emptied
// first only if an earlier run of this script made it (it holds the marker file).
'use strict';

const childProcess = require('child_process');
const fs = require('fs');
const path = require('path');
const Ajv2020 = require('ajv/dist/2020');
const addFormats = require('ajv-formats');
const { numberFindings, numberSelfCheck } = require('./json_numbers');

const SOURCE = path.resolve(__dirname, '..', '..');
const SCHEMA_DIR = path.join(SOURCE, 'docs', 'schemas');
const SAMPLES = path.join(SOURCE, 'decks', 'samples');
const AIRFOILS = path.join(SOURCE, 'decks', 'airfoils');
const MARKER = '.validate_schemas';
const ID = (name) => `https://parsons.invalid/schemas/${name}/1`;
const SCHEMA_FILES = {
  report: 'report.schema.json',
  events: 'events.schema.json',
  state: 'state.schema.json',
  profile: 'profile.schema.json',
  'json-output': 'json-output.schema.json',
  job: 'job.schema.json',
};

// Stop reasons no command line can provoke, and why. Every other reason of the schema's enum
// must appear in a report, a state or an events file of the runs below.
const NOT_PROVOKED = {
  tap_refused:
    "run's pre-scan refuses every deck whose tap card the cabinet would refuse (exit 2, no " +
    'report), with the same profile and the same limits as the cabinet (tool on no head, speed ' +
    'above max_rpm, a feed the sync drive cannot follow); unlike condition and sync cards, a ' +
    'tap card leaves nothing in a saved state that a resume could carry past the pre-scan',
  segment_refused:
    "run's pre-scan refuses every deck with a segment card under a profile without contouring " +
    '(exit 2, no report), and a state saved by a machine with contouring is refused by one ' +
    'without it, so no resume carries a segment card past the pre-scan',
};

const started = Date.now();
const failures = [];
const seen = new Set(); // coverage tags
let filesChecked = 0;
let documentsChecked = 0;
let runs = 0;

function fail(message) {
  failures.push(message);
  console.log(`FAIL  ${message}`);
}

// ---------------------------------------------------------------------------------------------
// Arguments and the work folder

function usage() {
  console.error('usage: node tests/js/validate_schemas.js PARSONS_EXE WORK_DIR');
  process.exit(2);
}

if (process.argv.length !== 4) {
  usage();
}
const EXE = path.resolve(process.argv[2]);
const WORK = path.resolve(process.argv[3]);
if (!fs.existsSync(EXE)) {
  console.error(`validate_schemas: no executable at ${EXE}`);
  process.exit(2);
}
if (fs.existsSync(WORK)) {
  const entries = fs.readdirSync(WORK);
  if (entries.length > 0 && !entries.includes(MARKER)) {
    console.error(`validate_schemas: ${WORK} is not empty and was not made by this script ` +
                  `(no ${MARKER} in it): give an empty or new folder`);
    process.exit(2);
  }
  for (const entry of entries) {
    fs.rmSync(path.join(WORK, entry), { recursive: true, force: true });
  }
}
fs.mkdirSync(WORK, { recursive: true });
fs.writeFileSync(path.join(WORK, MARKER), 'made by tests/js/validate_schemas.js\n');
const inWork = (name) => path.join(WORK, name);

// ---------------------------------------------------------------------------------------------
// The schemas

const ajv = new Ajv2020({
  allErrors: true,
  // The schemas use if/then with `required` of keys defined elsewhere, types given once for a
  // union, and tuples whose tail is open: all valid 2020-12 that Ajv's extra lints dislike.
  strictRequired: false,
  strictTypes: false,
  strictTuples: false,
});
addFormats(ajv);
const schemas = {};
for (const [name, file] of Object.entries(SCHEMA_FILES)) {
  const schema = JSON.parse(fs.readFileSync(path.join(SCHEMA_DIR, file), 'utf8'));
  if (schema.$schema !== 'https://json-schema.org/draft/2020-12/schema' || schema.$id !== ID(name) ||
      !schema.title || !schema.description) {
    fail(`${file}: needs $schema 2020-12, $id ${ID(name)}, a title and a description`);
  }
  schemas[name] = schema;
  ajv.addSchema(schema);
}
const coverage = require('./schema_coverage');
coverage.init(seen, schemas);
const { AXES, tag, requiredTags } = coverage;
const { negativeCases } = require('./schema_negative');
const validators = {};
for (const name of Object.keys(SCHEMA_FILES)) {
  validators[name] = ajv.getSchema(ID(name));
}

// ---------------------------------------------------------------------------------------------
// Running parsons

function describe(args) {
  return ['parsons', ...args].join(' ');
}

// Runs parsons in WORK_DIR and checks its exit status; returns the result (stdout as a string).
function run(args, options = {}) {
  const codes = options.codes || [0];
  runs += 1;
  const r = childProcess.spawnSync(EXE, args, {
    cwd: WORK,
    input: options.input,
    encoding: 'utf8',
    maxBuffer: 256 * 1024 * 1024,
  });
  if (r.error) {
    fail(`${describe(args)}: ${r.error.message}`);
    return r;
  }
  if (!codes.includes(r.status)) {
    fail(`${describe(args)}: exit ${r.status} (expected ${codes.join(' or ')})\n` +
         (r.stderr || '').trim().split('\n').slice(-5).map((l) => `        ${l}`).join('\n'));
  }
  if (options.stdout) {
    fs.writeFileSync(inWork(options.stdout), r.stdout || '');
  }
  return r;
}

// Runs parsons with its events stream on standard output and sends it SIGINT once `bytes` of
// the stream have arrived: the operator's Ctrl-C, at a moment when the run is surely under way.
function runInterrupted(args, eventsFile, bytes) {
  return new Promise((resolve) => {
    runs += 1;
    const child = childProcess.spawn(EXE, args, { cwd: WORK, stdio: ['ignore', 'pipe', 'pipe'] });
    child.on('error', (e) => fail(`${describe(args)}: ${e.message}`));
    const out = fs.openSync(inWork(eventsFile), 'w');
    let received = 0;
    let signalled = false;
    let stderr = '';
    child.stdout.on('data', (chunk) => {
      fs.writeSync(out, chunk);
      received += chunk.length;
      if (!signalled && received >= bytes) {
        signalled = true;
        child.kill('SIGINT');
      }
    });
    child.stderr.on('data', (chunk) => { stderr += chunk; });
    child.on('close', (code) => {
      fs.closeSync(out);
      if (!signalled) {
        fail(`${describe(args)}: the run ended before ${bytes} bytes of events arrived; ` +
             'no SIGINT was sent');
      } else if (code !== 130) {
        fail(`${describe(args)}: exit ${code} after SIGINT (expected 130)\n        ${stderr.trim()}`);
      }
      resolve();
    });
  });
}

// ---------------------------------------------------------------------------------------------
// Validating

const pending = []; // [file, schema] to validate once every run is done

function expect(file, schema) {
  pending.push([file, schema]);
}

function pointerText(error) {
  return error.instancePath === '' ? '(the document)' : error.instancePath;
}

// Ajv's message, without the whole of a long pattern.
function messageText(error) {
  const m = error.message || '';
  return m.length > 160 ? `${m.slice(0, 157)}...` : m;
}

function errorLines(errors) {
  return errors.slice(0, 6).map((e) => {
    const params = e.keyword === 'additionalProperties' ? ` (${e.params.additionalProperty})`
      : e.keyword === 'enum' ? ` (${JSON.stringify(e.params.allowedValues).slice(0, 120)})` : '';
    return `        at ${pointerText(e)}: ${messageText(e)}${params} [${e.schemaPath}]`;
  });
}

function validateFile(file, schema) {
  const full = inWork(file);
  if (!fs.existsSync(full)) {
    fail(`${file}: not written (expected a ${schema} document)`);
    return;
  }
  const text = fs.readFileSync(full, 'utf8');
  const validate = validators[schema];
  let count = 0;
  let bad = 0;
  const check = (where, body) => {
    count += 1;
    let doc;
    try {
      doc = JSON.parse(body);
    } catch (e) {
      bad += 1;
      fail(`${file}${where}: not JSON: ${e.message}`);
      return;
    }
    if (!validate(doc)) {
      bad += 1;
      if (bad <= 5) {
        fail(`${file}${where} against ${SCHEMA_FILES[schema]}:\n${errorLines(validate.errors).join('\n')}`);
      }
      return;
    }
    const numbers = numberFindings(body, schema); // as written, not as parsed (json_numbers.js)
    if (numbers.length > 0) {
      bad += 1;
      if (bad <= 5) {
        fail(`${file}${where}: ${numbers.length} number(s) not as docs/report.md rounds them:\n` +
             numbers.slice(0, 6).map((n) => `        ${n}`).join('\n'));
      }
      return;
    }
    tag(schema, doc, file);
  };
  if (file.endsWith('.jsonl')) {
    // JSON lines: each line one document, every line ended by a line feed.
    let at = 0;
    while (at < text.length) {
      const end = text.indexOf('\n', at);
      if (end < 0) {
        fail(`${file}: the last line has no line end`);
      }
      check(` line ${count + 1}`, text.slice(at, end < 0 ? text.length : end));
      at = end < 0 ? text.length : end + 1;
    }
    if (count === 0) {
      fail(`${file}: empty (an events stream ends with its finish line at least)`);
    }
  } else {
    check('', text);
  }
  if (bad > 5) {
    fail(`${file}: ${bad} documents failed in all (the first 5 shown)`);
  }
  filesChecked += 1;
  documentsChecked += count;
  const status = bad === 0 ? 'ok  ' : 'FAIL';
  console.log(`${status}  ${file.padEnd(44)} ${SCHEMA_FILES[schema].padEnd(24)} ` +
              `${String(count).padStart(7)} document${count === 1 ? '' : 's'}`);
}

// ---------------------------------------------------------------------------------------------
// Inputs made in WORK_DIR from the shipped samples

function writeWork(name, text) {
  fs.writeFileSync(inWork(name), text);
}

function replaceLine(text, from, to) {
  if (!text.includes(from)) {
    throw new Error(`sample changed: no line "${from}"`);
  }
  return text.replace(from, to);
}

// A text card image ("~raw" then 80 columns of four octal digits) with one more hole in a column.
function punchMore(deckText, card, column, rowBit) {
  const lines = deckText.split('\n');
  const line = lines[card - 1];
  const at = 4 + (column - 1) * 4;
  const word = parseInt(line.slice(at, at + 4), 8) | rowBit;
  lines[card - 1] = line.slice(0, at) + word.toString(8).padStart(4, '0') + line.slice(at + 4);
  return lines.join('\n');
}

// ---------------------------------------------------------------------------------------------
// The runs

async function runAll() {
  const sample = path.join(SAMPLES, 'patent-example.csv');
  const conditions = path.join(SAMPLES, 'condition-cards.csv');
  const pressSync = path.join(SAMPLES, 'press-sync.csv');
  const pressReset = path.join(SAMPLES, 'press-reset.csv');
  const everyCondition = path.join(SAMPLES, 'every-condition.csv');
  const sampleText = fs.readFileSync(sample, 'utf8');
  const conditionText = fs.readFileSync(conditions, 'utf8');
  const X = ['--profile', 'parsons-extended'];

  // Profiles: the default and each built-in one by name.
  run(['profile'], { stdout: 'profile-default.json' });
  expect('profile-default.json', 'profile');
  for (const name of schemas.profile.properties.base.enum) {
    run(['profile', '--profile', name], { stdout: `profile-${name}.json` });
    expect(`profile-${name}.json`, 'profile');
  }
  // Profile files applied over a built-in one (printed whole).
  writeWork('press-stops.json', JSON.stringify({ base: 'parsons-extended', name: 'press-stops',
                                                 press: { stop_cycle: 1, stop_angle_deg: 10 } }));
  writeWork('press-stops-in-sync.json', JSON.stringify({ base: 'parsons-extended', name: 'press-stops-in-sync',
                                                         press: { stop_cycle: 1, stop_angle_deg: 40 } }));
  writeWork('short-vertical.json', JSON.stringify({ name: 'short-vertical',
                                                    axes: { vertical: { travel_max_in: 2.0 } } }));
  run(['profile', '--profile', 'press-stops.json'], { stdout: 'profile-press-stops.json' });
  expect('profile-press-stops.json', 'profile');

  // The sample deck, whole: report, events, path (no state: it completes).
  run(['run', sample, '-q', '--report', 'sample.report.json', '--events', 'sample.events.jsonl',
       '--save-state', 'sample.state.json', '--path', 'sample.path.csv']);
  expect('sample.report.json', 'report');
  expect('sample.events.jsonl', 'events');
  if (fs.existsSync(inWork('sample.state.json'))) {
    fail('sample.state.json: a run that completes writes no state');
  }
  // Faults that leave the deck running (a slip under the patent's measuring chain, a fault that
  // never comes into play).
  run(['run', sample, '-q', '--fault', 'slip:table:2000:25', '--fault', 'drop-impulse:table:99999',
       '--report', 'slip.report.json']);
  expect('slip.report.json', 'report');

  // Stopped by each check (exit 3): report, events, saved state.
  const stops = [
    ['check-mismatch', ['--fault', 'stuck-relay:table:354:1']],
    ['missed-impulse', ['--fault', 'drop-impulse:table:120']],
    ['out-of-order', ['--fault', 'feed-twice:2']],
    ['bad-punch', ['--fault', 'short-card:2']],
    ['soft-limit', ['--limit', 'vertical=0:2.5']],
    ['limit-switch', ['--profile', 'short-vertical.json']],
  ];
  for (const [name, extra] of stops) {
    run(['run', sample, '-q', ...extra, '--report', `${name}.report.json`, '--events',
         `${name}.events.jsonl`, '--save-state', `${name}.state.json`], { codes: [3] });
    expect(`${name}.report.json`, 'report');
    expect(`${name}.events.jsonl`, 'events');
    expect(`${name}.state.json`, 'state');
  }
  // Resumed (exit 0): the soft limit widened.
  run(['run', sample, '-q', '--resume', 'soft-limit.state.json', '--limit', 'vertical=-0.1:3',
       '--report', 'resumed.report.json', '--events', 'resumed.events.jsonl']);
  expect('resumed.report.json', 'report');
  expect('resumed.events.jsonl', 'events');
  // A deck from standard input (no fingerprint of the cards machined in its state).
  run(['run', '-', '--format', 'listing', '-q', '--limit', 'table=0:5', '--report',
       'stdin.report.json', '--save-state', 'stdin.state.json'], { codes: [3], input: sampleText });
  expect('stdin.report.json', 'report');
  expect('stdin.state.json', 'state');

  // A sequence stall: table and cross punched at position 2 only on card 1.
  let stall = replaceLine(sampleText, '1,0,table,+,1,8.785,8.885,8.985,8.985,12',
                          '1,0,table,+,1,8.785,8.885,8.985,8.985,2');
  stall = replaceLine(stall, '1,0,cross,+,2,2.300,,2.500,2.500,12', '1,0,cross,+,2,2.300,,2.500,2.500,2');
  writeWork('stall.csv', stall);
  // Advice: card 1's cross starts on speed 2 with its slow-down left blank.
  writeWork('advice.csv', replaceLine(sampleText, '1,0,cross,+,2,2.300,,2.500,2.500,12',
                                      '1,0,cross,+,2,,,2.500,2.500,12'));
  run(['run', 'stall.csv', '-q', '--report', 'stall.report.json', '--events', 'stall.events.jsonl',
       '--save-state', 'stall.state.json'], { codes: [3] });
  expect('stall.report.json', 'report');
  expect('stall.events.jsonl', 'events');
  expect('stall.state.json', 'state');

  // Text card images with a double punch (card 1, table stop thousandths: rows 5 and 9) and a
  // stray hole (card 2, the same column: row 12).
  run(['punch', sample, '-o', 'sample.txt', '--json'], { stdout: 'punch-text.json' });
  expect('punch-text.json', 'json-output');
  run(['punch', sample, '-o', 'sample.cbn', '--code', '026', '--json'], { stdout: 'punch-cbn.json' });
  expect('punch-cbn.json', 'json-output');
  const deckText = fs.readFileSync(inWork('sample.txt'), 'utf8');
  writeWork('double-punch.txt', punchMore(deckText, 1, 15, 0o001));
  writeWork('stray-hole.txt', punchMore(deckText, 2, 15, 0o4000));
  run(['run', 'stray-hole.txt', '-q', '--report', 'stray-hole.report.json'], { codes: [3] });
  expect('stray-hole.report.json', 'report');

  // Ctrl-C (exit 130): the events on standard output, SIGINT once 256 KiB of them arrived.
  await runInterrupted(['run', sample, '-q', '--events', '-', '--report', 'interrupted.report.json',
                        '--save-state', 'interrupted.state.json'], 'interrupted.events.jsonl', 256 * 1024);
  expect('interrupted.report.json', 'report');
  expect('interrupted.events.jsonl', 'events');
  expect('interrupted.state.json', 'state');

  // Condition cards (EP 0640901): the sample, one not met, and one refused by the cabinet.
  run(['run', conditions, ...X, '-q', '--report', 'conditions.report.json', '--events',
       'conditions.events.jsonl']);
  expect('conditions.report.json', 'report');
  expect('conditions.events.jsonl', 'events');
  // An every-condition (an addition): its firings in the report and the events, and a state
  // saved with it standing (stopped by a soft limit on the table's way back).
  run(['run', everyCondition, ...X, '-q', '--report', 'every.report.json', '--events',
       'every.events.jsonl']);
  expect('every.report.json', 'report');
  expect('every.events.jsonl', 'events');
  if (JSON.parse(fs.readFileSync(inWork('every.report.json'), 'utf8')).actions.map((a) => a.firing).join() !== '1,2') {
    fail('every.report.json: the every-condition did not fire twice (firings 1, 2)');
  }
  run(['run', everyCondition, ...X, '-q', '--limit', 'table=0.150:5', '--save-state',
       'every.state.json'], { codes: [3] });
  expect('every.state.json', 'state');
  writeWork('condition-not-met.csv', replaceLine(conditionText, '1,if,7,table,+,5.000,lamp,3',
                                                 '1,if,7,table,+,9.500,lamp,3'));
  run(['run', 'condition-not-met.csv', ...X, '-q', '--report', 'condition-not-met.report.json',
       '--save-state', 'condition-not-met.state.json'], { codes: [3] });
  expect('condition-not-met.report.json', 'report');
  expect('condition-not-met.state.json', 'state');
  // condition_refused: run's pre-scan refuses a deck whose condition cards the cabinet cannot
  // take, so the cabinet meets one only in a deck the pre-scan could not judge: stop card 2 of
  // the sample (its conditions stored in buffer PFR), then resume it on a corrected deck whose
  // card 2 no longer moves the cross slide that event 8 watches.
  run(['run', conditions, ...X, '-q', '--limit', 'table=0:5', '--save-state',
       'conditions-stored.state.json'], { codes: [3] });
  expect('conditions-stored.state.json', 'state');
  const motionCard1 = AXES.map((a) => `1,0,${a},+,3,,,0.000,0.000,1`).join('\n');
  let refused = conditionText.split('\n').filter((l) => !l.startsWith('1,if')).join('\n');
  refused = replaceLine(refused, '2,,table,+,1,', `${motionCard1}\n2,,table,+,1,`);
  refused = replaceLine(refused, '2,,cross,+,2,2.300,,2.500,2.500,12', '2,,cross,+,3,,,0.000,0.000,12');
  writeWork('condition-refused.csv', refused);
  run(['run', 'condition-refused.csv', '-q', '--resume', 'conditions-stored.state.json', '--report',
       'condition-refused.report.json', '--events', 'condition-refused.events.jsonl'], { codes: [3] });
  expect('condition-refused.report.json', 'report');
  expect('condition-refused.events.jsonl', 'events');
  // tool_change_interlock: the sample with its card 2 turning the spindle forward (column 1 0)
  // while event 8's tool change trips.
  writeWork('tool-change-interlock.csv',
            conditionText.split('\n').map((l) => l.replace(/^2,,/, '2,0,')).join('\n'));
  run(['run', 'tool-change-interlock.csv', ...X, '-q', '--report', 'tool-change-interlock.report.json',
       '--events', 'tool-change-interlock.events.jsonl'], { codes: [3] });
  expect('tool-change-interlock.report.json', 'report');
  expect('tool-change-interlock.events.jsonl', 'events');

  // Press synchronisation (EP 0436887): the sample, a press that stops (the card waits for an
  // angle it never reaches; the crank stops under a speed-synchronised axis), and a sync card
  // refused by the cabinet (resumed past the pre-scan as above).
  run(['run', pressSync, ...X, '-q', '--report', 'press-sync.report.json', '--events',
       'press-sync.events.jsonl']);
  expect('press-sync.report.json', 'report');
  expect('press-sync.events.jsonl', 'events');
  // Claim 5: a sync card's reset order (switch 16A, register_resets in the report).
  run(['run', pressReset, ...X, '-q', '--report', 'press-reset.report.json', '--events',
       'press-reset.events.jsonl']);
  expect('press-reset.report.json', 'report');
  expect('press-reset.events.jsonl', 'events');
  if (JSON.parse(fs.readFileSync(inWork('press-reset.report.json'), 'utf8')).press.register_resets !== 1) {
    fail('press-reset.report.json: press.register_resets is not 1');
  }
  run(['run', pressSync, '--profile', 'press-stops.json', '-q', '--report', 'sync-timeout.report.json',
       '--save-state', 'sync-timeout.state.json'], { codes: [3] });
  expect('sync-timeout.report.json', 'report');
  expect('sync-timeout.state.json', 'state');
  run(['run', pressSync, '--profile', 'press-stops-in-sync.json', '-q', '--report',
       'sync-timeout-axis.report.json'], { codes: [3] });
  expect('sync-timeout-axis.report.json', 'report');
  run(['run', pressSync, ...X, '-q', '--limit', 'table=0:0.3', '--save-state',
       'sync-pending.state.json'], { codes: [3] });
  expect('sync-pending.state.json', 'state');
  const still = (card, axis, seq) => `${card},,${axis},+,3,,,0.000,0.000,${seq}`;
  writeWork('sync-refused.csv', [
    'card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq',
    ...AXES.map((a) => still(1, a, 1)),
    still(2, 'table', 5), '2,,cross,+,3,,,0.100,0.100,4', still(2, 'vertical', 1),
    still(2, 'swivel', 2), still(2, 'tilt', 3), '',
  ].join('\n'));
  run(['run', 'sync-refused.csv', '-q', '--resume', 'sync-pending.state.json', '--report',
       'sync-refused.report.json', '--events', 'sync-refused.events.jsonl'], { codes: [3] });
  expect('sync-refused.report.json', 'report');
  expect('sync-refused.events.jsonl', 'events');

  // gen airfoil: template (with centres), a female template from a .dat file, a wing; each cut
  // proved.
  run(['gen', 'airfoil', '--naca', '2412', '--chord', '6', '--scallop', '0.002', '-o', 'naca2412.cbn',
       '--centres', 'naca2412-centres.csv', '--json'], { stdout: 'gen-airfoil-template.json' });
  expect('gen-airfoil-template.json', 'json-output');
  expect('naca2412.cbn.job.json', 'job');
  run(['run', 'naca2412.cbn', '-q', '--cut', 'naca2412-cut.svg', '--report', 'naca2412.report.json']);
  expect('naca2412.report.json', 'report');
  run(['gen', 'airfoil', '--dat', path.join(AIRFOILS, 'clarky.dat'), '--female', '--surface', 'lower',
       '--cutter-radius', '0.05', '--scallop', '0.004', '-o', 'clarky.csv', '--json'],
      { stdout: 'gen-airfoil-dat.json' });
  expect('gen-airfoil-dat.json', 'json-output');
  expect('clarky.csv.job.json', 'job');
  run(['gen', 'airfoil', '--naca', '2412', '--closed-te', '--surface', 'both', '--stations', '30',
       '-o', 'both.bin', '--json'], { stdout: 'gen-airfoil-both.json' });
  expect('gen-airfoil-both.json', 'json-output');
  expect('both.bin.job.json', 'job');
  run(['gen', 'airfoil', '--naca', '0012', '--job', 'wing', '--chord', '4', '--span', '5', '--taper',
       '0.6', '--sweep', '10', '--scallop', '0.002', '-o', 'wing.cbn', '--json'],
      { stdout: 'gen-airfoil-wing.json' });
  expect('gen-airfoil-wing.json', 'json-output');
  expect('wing.cbn.job.json', 'job');
  run(['run', 'wing.cbn', '-q', '--cut', 'wing-cut.svg', '--report', 'wing.report.json']);
  expect('wing.report.json', 'report');

  // A deck to a device has no job description beside it (job_file null), unless --job-out
  // names one (and a press or tapping job's profile beside that). The device is a null device of
  // this folder's own (mknod 1 3), never the machine's /dev/null (issue 53); where mknod is not
  // permitted (not root) these four are skipped.
  const made = childProcess.spawnSync('mknod', ['-m', '666', path.join(WORK, 'null'), 'c', '1', '3'],
                                      { encoding: 'utf8' });
  if (made.status === 0) {
    run(['gen', 'airfoil', '--naca', '2412', '--stations', '10', '--to', 'cbn', '-o', 'null',
         '--json'], { stdout: 'gen-airfoil-device.json' });
    expect('gen-airfoil-device.json', 'json-output');
    run(['gen', 'two-tool', '--naca', '2412', '--to', 'cbn', '-o', 'null', '--json'],
        { stdout: 'gen-two-tool-device.json' });
    expect('gen-two-tool-device.json', 'json-output');
    run(['gen', 'tapping', '--to', 'cbn', '-o', 'null', '--json'],
        { stdout: 'gen-tapping-device.json' });
    expect('gen-tapping-device.json', 'json-output');
    run(['gen', 'press-feeder', '--to', 'cbn', '-o', 'null', '--job-out', 'kept-feeder.json',
         '--json'], { stdout: 'gen-press-feeder-job-out.json' });
    expect('gen-press-feeder-job-out.json', 'json-output');
    expect('kept-feeder.json', 'job');
    expect('kept-feeder.profile.json', 'profile');
  } else {
    console.log('  skipped: a deck to a device (mknod is not permitted here: ' +
                (made.stderr || '').trim() + ')');
  }

  // gen two-tool (both variants), its cut proved under parsons-extended.
  run(['gen', 'two-tool', '--naca', '2412', '--chord', '6', '--scallop', '0.002', '-o', 'two-tool.csv',
       '--json'], { stdout: 'gen-two-tool.json' });
  expect('gen-two-tool.json', 'json-output');
  expect('two-tool.csv.job.json', 'job');
  run(['run', 'two-tool.csv', ...X, '-q', '--cut', 'two-tool-cut.svg', '--report', 'two-tool.report.json']);
  expect('two-tool.report.json', 'report');
  run(['gen', 'two-tool', '--naca', '2412', '--variant', 'boundary', '--scallop', '0.004', '-o',
       'boundary.cbn', '--json'], { stdout: 'gen-two-tool-boundary.json' });
  expect('gen-two-tool-boundary.json', 'json-output');
  expect('boundary.cbn.job.json', 'job');

  // gen press-feeder (both variants), each proved; and a job file made unsafe (its safe height
  // raised): the proof finds a collision (exit 3).
  for (const [deck, extra] of [['feeder.csv', []], ['feeder-speed-only.csv', ['--speed-only']]]) {
    const stem = deck.replace(/\.csv$/, '');
    run(['gen', 'press-feeder', ...extra, '-o', deck, '--json'], { stdout: `gen-${stem}.json` });
    expect(`gen-${stem}.json`, 'json-output');
    expect(`${deck}.job.json`, 'job');
    expect(`${deck}.profile.json`, 'profile');
    run(['run', deck, '-q', '--press-proof', `${deck}.job.json`, '--report', `${stem}.report.json`]);
    expect(`${stem}.report.json`, 'report');
  }
  const unsafe = JSON.parse(fs.readFileSync(inWork('feeder.csv.job.json'), 'utf8'));
  unsafe.safe_height_in = 3.5;
  writeWork('feeder-unsafe.job.json', `${JSON.stringify(unsafe, null, 2)}\n`);
  expect('feeder-unsafe.job.json', 'job');
  run(['run', 'feeder.csv', '-q', '--press-proof', 'feeder-unsafe.job.json', '--report',
       'feeder-collision.report.json'], { codes: [3] });
  expect('feeder-collision.report.json', 'report');

  // gen tapping: both ratio sources, proved; a stale ratio (wrong pitch, exit 3); a transfer
  // that hangs (transfer_timeout, exit 3), also at the first hole (no hole measured); a job
  // that knows only the first row (holes it does not know), with --thread-tolerance.
  for (const [deck, extra] of [['plate.csv', []], ['plate-stored.csv', ['--ratio-source', 'stored']],
    ['plate-row.csv', ['--rows', '1']], ['plate-21.csv', ['--tools', '2', '1']],
    ['plate-peck.csv', ['--peck', '0.2']]]) {
    const stem = deck.replace(/\.csv$/, '');
    run(['gen', 'tapping', ...extra, '-o', deck, '--json'], { stdout: `gen-${stem}.json` });
    expect(`gen-${stem}.json`, 'json-output');
    expect(`${deck}.job.json`, 'job');
    expect(`${deck}.profile.json`, 'profile');
  }
  run(['run', 'plate.csv', '-q', '--thread-proof', 'plate.csv.job.json', '--report', 'plate.report.json',
       '--events', 'plate.events.jsonl']);
  expect('plate.report.json', 'report');
  expect('plate.events.jsonl', 'events');
  run(['run', 'plate-stored.csv', '-q', '--thread-proof', 'plate-stored.csv.job.json', '--report',
       'plate-stored.report.json']);
  expect('plate-stored.report.json', 'report');
  run(['run', 'plate.csv', '-q', '--profile', 'plate.csv.profile.json', '--report', 'plate-plain.report.json']);
  expect('plate-plain.report.json', 'report');
  run(['run', 'plate.csv', '-q', '--thread-proof', 'plate.csv.job.json', '--fault', 'stale-ratio:1',
       '--report', 'stale-ratio.report.json'], { codes: [3] });
  expect('stale-ratio.report.json', 'report');
  run(['run', 'plate.csv', '-q', '--thread-proof', 'plate.csv.job.json', '--fault', 'transfer-hang:1',
       '--report', 'transfer-hang.report.json', '--save-state', 'transfer-hang.state.json'], { codes: [3] });
  expect('transfer-hang.report.json', 'report');
  expect('transfer-hang.state.json', 'state');
  run(['run', 'plate-21.csv', '-q', '--thread-proof', 'plate-21.csv.job.json', '--fault',
       'transfer-hang:1', '--report', 'transfer-hang-first.report.json', '--events',
       'transfer-hang-first.events.jsonl'], { codes: [3] });
  expect('transfer-hang-first.report.json', 'report');
  expect('transfer-hang-first.events.jsonl', 'events');
  run(['run', 'plate.csv', '-q', '--profile', 'plate.csv.profile.json', '--thread-proof',
       'plate-row.csv.job.json', '--thread-tolerance', '10', '--report', 'plate-unknown-holes.report.json'],
      { codes: [3] });
  expect('plate-unknown-holes.report.json', 'report');
  // Rigid peck tapping (an addition): the holes' peck_in and pecks in the report and the state
  // (the table's limit stops the run on the way to hole 2, hole 1 tapped in three passes).
  run(['run', 'plate-peck.csv', '-q', '--thread-proof', 'plate-peck.csv.job.json', '--limit',
       'table=0:2', '--report', 'plate-peck.report.json', '--save-state', 'plate-peck.state.json'],
      { codes: [3] });
  expect('plate-peck.report.json', 'report');
  expect('plate-peck.state.json', 'state');

  // gen gcode: a small program in millimetres with arcs both ways (it writes no job file).
  writeWork('program.ngc', ['G21 G90 G17 (millimetres)', 'G0 Z5', 'M3 S800', 'G1 Z-1 F100', 'G1 X20',
    'G3 X30 Y10 I0 J10', 'G1 Y20', 'G2 X20 Y30 R10', 'G0 Z5', 'M2', ''].join('\n'));
  run(['gen', 'gcode', 'program.ngc', '-o', 'program.csv', '--json'], { stdout: 'gen-gcode.json' });
  expect('gen-gcode.json', 'json-output');

  // show --json: motion, condition, sync and tap cards; warnings; deck errors and bad punches
  // (both exit 2, the document printed first).
  const shows = [
    ['show-sample.json', [sample], [0]],
    ['show-stall.json', ['stall.csv'], [0]],
    ['show-conditions.json', [conditions, ...X], [0]],
    ['show-every.json', [everyCondition, ...X], [0]],
    ['show-press-sync.json', [pressSync, ...X], [0]],
    ['show-press-reset.json', [pressReset, ...X], [0]],
    ['show-plate.json', ['plate.csv', ...X], [0]],
    ['show-plate-peck.json', ['plate-peck.csv', ...X], [0]],
    ['show-stray-hole.json', ['stray-hole.txt'], [0]],
    ['show-double-punch.json', ['double-punch.txt'], [0]],
    ['show-deck-errors.json', [conditions], [2]],
  ];
  for (const [out, args, codes] of shows) {
    run(['show', ...args, '--json'], { stdout: out, codes });
    expect(out, 'json-output');
  }
  // check --json: a soft limit and a limit switch, a double punch read as two relays
  // (parsons-1952) and refused (parsons-safe), a stall, a condition never met, advice. (A deck
  // with deck errors is refused with exit 2 and no document, as run refuses it.)
  const checks = [
    ['check-clean.json', [sample], [0]],
    ['check-soft-limit.json', [sample, '--limit', 'table=0:8.9'], [3]],
    ['check-limit-switch.json', [sample, '--profile', 'short-vertical.json'], [3]],
    ['check-double-punch.json', ['double-punch.txt'], [3]],
    ['check-advice.json', ['advice.csv'], [0, 3]],
    ['check-double-punch-safe.json', ['double-punch.txt', '--profile', 'parsons-safe'], [3]],
    ['check-stall.json', ['stall.csv'], [3]],
    ['check-condition-not-met.json', ['condition-not-met.csv', ...X], [3]],
    ['check-plate.json', ['plate.csv', ...X], [0]],
  ];
  for (const [out, args, codes] of checks) {
    run(['check', ...args, '--json'], { stdout: out, codes });
    expect(out, 'json-output');
  }
}

// ---------------------------------------------------------------------------------------------
// The negative self-check: broken documents must fail

function negativeChecks() {
  const cases = negativeCases(inWork);

  let passedWrongly = 0;
  console.log('\nnegative self-check (each broken document must fail validation):');
  for (const c of cases) {
    let doc;
    try {
      doc = c.source();
    } catch (e) {
      fail(`negative check "${c.what}": cannot load its source document: ${e.message}`);
      continue;
    }
    if (doc === undefined) {
      fail(`negative check "${c.what}": no source document`);
      continue;
    }
    if (!validators[c.schema](doc)) {
      fail(`negative check "${c.what}": its source document is not valid to begin with`);
      continue;
    }
    c.mutate(doc);
    if (validators[c.schema](doc)) {
      passedWrongly += 1;
      fail(`negative check "${c.what}": the broken document PASSED ${SCHEMA_FILES[c.schema]}`);
    } else {
      const e = validators[c.schema].errors[0];
      console.log(`ok    fails as it should: ${c.what}: ${pointerText(e)} ${messageText(e)}`);
    }
  }
  return passedWrongly;
}

// ---------------------------------------------------------------------------------------------

async function main() {
  console.log(`parsons: ${EXE}`);
  console.log(`work folder: ${WORK}\n`);
  await runAll();
  console.log(`\n${pending.length} files to validate:`);
  for (const [file, schema] of pending) {
    validateFile(file, schema);
  }

  console.log('\ncoverage:');
  const required = requiredTags();
  let missing = 0;
  for (const t of required) {
    const reason = t.startsWith('stop reason ') ? NOT_PROVOKED[t.slice('stop reason '.length)] : undefined;
    if (seen.has(t)) {
      continue;
    }
    if (reason) {
      console.log(`not provoked (listed): ${t}: ${reason}`);
      continue;
    }
    missing += 1;
    fail(`coverage: no run showed "${t}" (a schema branch no output exercises)`);
  }
  for (const [reason] of Object.entries(NOT_PROVOKED)) {
    if (seen.has(`stop reason ${reason}`)) {
      console.log(`note: stop reason ${reason} is listed as not provoked, but a run showed it`);
    }
  }
  console.log(`${required.length - missing} of ${required.length} branches seen` +
              ` (${Object.keys(NOT_PROVOKED).length} listed as not provokable)`);

  const passedWrongly = negativeChecks() + numberSelfCheck(fail);
  const seconds = ((Date.now() - started) / 1000).toFixed(1);
  console.log(`\n${runs} runs of parsons; ${filesChecked} files, ${documentsChecked} documents ` +
              `validated; ${seconds} s in all; ` +
              `${failures.length} failure${failures.length === 1 ? '' : 's'}` +
              (passedWrongly ? ` (${passedWrongly} broken documents passed)` : ''));
  process.exit(failures.length === 0 ? 0 : 1);
}

main().catch((e) => {
  console.error(e.stack || String(e));
  process.exit(1);
});
