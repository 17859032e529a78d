// The negative self-check of tests/js/validate_schemas.js: documents its runs wrote, each broken
// one way (a required key deleted, an unknown key added, a number turned into a string, ...),
// which the schemas must refuse. negativeCases(inWork) lists them; the script validates them.
'use strict';

const fs = require('fs');

function negativeCases(inWork) {
  const load = (file) => JSON.parse(fs.readFileSync(inWork(file), 'utf8'));
  const firstLine = (file, pred) => fs.readFileSync(inWork(file), 'utf8').split('\n')
    .filter(Boolean).map((l) => JSON.parse(l)).find(pred);
  const cases = [];
  const add = (what, schema, source, mutate) => cases.push({ what, schema, source, mutate });
  // The three the brief asks for, on the sample's report.
  add('report: a required key deleted (machine_seconds)', 'report', () => load('sample.report.json'),
      (d) => { delete d.machine_seconds; });
  add('report: an unknown key added', 'report', () => load('sample.report.json'),
      (d) => { d.unexpected_key = 1; });
  add('report: a number turned into a string (machine_seconds)', 'report', () => load('sample.report.json'),
      (d) => { d.machine_seconds = String(d.machine_seconds); });
  // Deeper in the report and in the other formats.
  add('report: an unknown key in axes.table', 'report', () => load('sample.report.json'),
      (d) => { d.axes.table.unexpected_key = 0; });
  add('report: a required key deleted in a stop (lamps)', 'report', () => load('check-mismatch.report.json'),
      (d) => { delete d.stop.lamps; });
  add('report: an unknown stop reason', 'report', () => load('check-mismatch.report.json'),
      (d) => { d.stop.reason = 'unexpected_reason'; });
  add('report: a stop with status completed', 'report', () => load('check-mismatch.report.json'),
      (d) => { d.status = 'completed'; });
  add('report: schema_version 2', 'report', () => load('sample.report.json'),
      (d) => { d.schema_version = 2; });
  add('report: an unknown key in a proved hole', 'report', () => load('plate.report.json'),
      (d) => { d.tapping.holes[0].unexpected_key = true; });
  add('events: an unknown key on a signal line', 'events',
      () => firstLine('sample.events.jsonl', (l) => !('event' in l)), (d) => { d.unexpected_key = 1; });
  add('events: an unknown event kind', 'events',
      () => firstLine('sample.events.jsonl', (l) => l.event === 'finish'), (d) => { d.event = 'unexpected'; });
  add('events: a card line without its number', 'events',
      () => firstLine('sample.events.jsonl', (l) => l.event === 'card'), (d) => { delete d.number; });
  add('events: an unknown signal', 'events',
      () => firstLine('sample.events.jsonl', (l) => !('event' in l)), (d) => { d.signal = 'table.unexpected_999'; });
  add('events: a condition line with a string id', 'events',
      () => firstLine('conditions.events.jsonl', (l) => l.event === 'condition_met'), (d) => { d.id = String(d.id); });
  add('events: a stop line with axis null for check_mismatch', 'events',
      () => firstLine('check-mismatch.events.jsonl', (l) => l.event === 'stop'), (d) => { d.axis = null; });
  add('state: an unknown key in a stepping switch', 'state', () => load('check-mismatch.state.json'),
      (d) => { d.resume.axes.table.absolute_counter.switches_104_to_110[0].unexpected_key = 0; });
  add('state: a profile key deleted', 'state', () => load('check-mismatch.state.json'),
      (d) => { delete d.profile.reader_cycle_s; });
  add('profile: an unknown key', 'profile', () => load('profile-parsons-extended.json'),
      (d) => { d.unexpected_key = 1; });
  add('profile: a duration out of range (reader_cycle_s 61)', 'profile', () => load('profile-parsons-1952.json'),
      (d) => { d.reader_cycle_s = 61; });
  add('json-output: an unknown key in a show card', 'json-output', () => load('show-sample.json'),
      (d) => { d.cards[0].unexpected_key = 1; });
  add('json-output: an unknown command', 'json-output', () => load('punch-text.json'),
      (d) => { d.command = 'unexpected'; });
  add('json-output: a limit finding without limit_kind', 'json-output', () => load('check-soft-limit.json'),
      (d) => { delete d.findings[0].limit_kind; });
  add('job: a template job without work_zero_in', 'job', () => load('naca2412.cbn.job.json'),
      (d) => { delete d.work_zero_in; });
  add('job: an unknown key in a tapping hole', 'job', () => load('plate.csv.job.json'),
      (d) => { d.holes[0].unexpected_key = 1; });
  return cases;
}

module.exports = { negativeCases };
