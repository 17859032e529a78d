// The coverage of tests/js/validate_schemas.js: what each valid document shows of the schemas'
// branches (the tags a document earns), and the tags the schemas' enums and branches require.
// init() hands it the script's set of tags seen and its schemas by name.
'use strict';

let seen = new Set();
let schemas = {};

function init(seenTags, schemasByName) {
  seen = seenTags;
  schemas = schemasByName;
}

const AXES = ['table', 'cross', 'vertical', 'swivel', 'tilt'];
const SCOPES = [...AXES, 'cabinet', 'conditions', 'press', 'spindle'];

function tagStop(reason) {
  seen.add(`stop reason ${reason}`);
}

function tag(schema, doc, file) {
  switch (schema) {
    case 'events':
      if (doc.event === undefined) {
        seen.add(`events: signal line of scope ${doc.signal.split('.')[0]}`);
      } else {
        seen.add(`events: event kind ${doc.event}`);
        if (doc.event === 'stop') {
          tagStop(doc.reason);
        }
      }
      break;
    case 'report':
      seen.add(`report: status ${doc.status}`);
      if (doc.stop) {
        tagStop(doc.stop.reason);
      }
      if (doc.cut) {
        seen.add(`report: cut of a ${'root' in doc.cut ? 'wing' : 'passes' in doc.cut ? 'two-tool' : 'template'} job`);
      }
      if ('tool_in_spindle' in doc) {
        seen.add('report: condition units');
        if (doc.actions.length > 0) {
          seen.add('report: actions');
        }
      }
      if (doc.press) {
        seen.add(`report: press${'proof_cycles' in doc.press ? ' with --press-proof' : ''}`);
        if (doc.press.collision) {
          seen.add('report: press proof with a collision');
        }
      }
      if (doc.tapping) {
        const proved = 'holes_flagged' in doc.tapping;
        seen.add(`report: tapping${proved ? ' with --thread-proof' : ''}`);
        if (proved) {
          if (doc.tapping.worst_hole === null) {
            seen.add('report: thread proof with no hole measured');
          }
          if (doc.tapping.thread_tolerance_percent !== null) {
            seen.add('report: thread proof with --thread-tolerance');
          }
          for (const h of doc.tapping.holes) {
            if (!h.measured) {
              seen.add('report: thread proof of a hole not measured');
            }
            if (h.hole === null) {
              seen.add('report: thread proof of a tap card the job does not know');
            }
          }
        }
      }
      if (doc.profile_applied.file !== null) {
        seen.add('report: a profile file');
      }
      if (doc.profile_applied.differs_from_named.length > 0) {
        seen.add('report: a profile that differs from its named one');
      }
      for (const a of AXES) {
        if (/^saved state /.test(doc.profile_applied.limits[a].limit_switches.from)) {
          seen.add('report: a resumed run');
        }
      }
      break;
    case 'state':
      tagStop(doc.stop.reason);
      seen.add(`state: condition units ${doc.resume.conditions === null ? 'absent' : 'present'}`);
      seen.add(`state: press synchronisation ${doc.resume.sync === null ? 'absent' : 'present'}`);
      seen.add(`state: spindle synchronisation ${doc.resume.tapping === null ? 'absent' : 'present'}`);
      if (doc.resume.sync && doc.resume.sync.units.synchronisation_processor_17.pending) {
        seen.add('state: a sync card waiting for its motion card');
      }
      if (doc.cards_machined === null) {
        seen.add('state: a deck from standard input');
      }
      break;
    case 'profile':
      seen.add(`profile: ${/\.profile\.json$/.test(file) ? 'written by gen' : `named ${doc.name}`}`);
      break;
    case 'job':
      seen.add(`job: ${doc.job}`);
      break;
    case 'json-output':
      seen.add(`json-output: command ${doc.command}`);
      if (doc.command === 'gen') {
        seen.add(`json-output: gen ${doc.generator}${doc.generator === 'airfoil' ? ` ${doc.job}` : ''}`);
      }
      if (doc.command === 'show') {
        for (const card of doc.cards) {
          seen.add(`json-output: show card ${'bad_punch' in card ? 'bad_punch' : card.kind || 'motion'}`);
          if (card.deck_errors) {
            seen.add('json-output: show card with deck_errors');
          }
          if (card.warnings && card.warnings.length > 0) {
            seen.add('json-output: show card with warnings');
          }
        }
      }
      if (doc.command === 'check') {
        for (const f of doc.findings) {
          seen.add(`json-output: check finding ${f.kind}`);
          if (f.kind === 'limit') {
            seen.add(`json-output: check limit_kind ${f.limit_kind}`);
          }
        }
      }
      break;
    default:
      break;
  }
}

// Every tag the runs must have shown: from the schemas' own enums where they have one, so that a
// value added to a schema without a run that shows it fails here.
function requiredTags() {
  const ev = schemas.events.$defs;
  const jo = schemas['json-output'].$defs;
  const tags = [];
  for (const kind of ev.event_kind.enum) {
    tags.push(`events: event kind ${kind}`);
  }
  for (const scope of SCOPES) {
    tags.push(`events: signal line of scope ${scope}`);
  }
  for (const reason of ev.stop_reason.enum) {
    tags.push(`stop reason ${reason}`);
  }
  for (const status of schemas.report.properties.status.enum) {
    tags.push(`report: status ${status}`);
  }
  tags.push(
    'report: cut of a template job', 'report: cut of a wing job', 'report: cut of a two-tool job',
    'report: condition units', 'report: actions', 'report: press', 'report: press with --press-proof',
    'report: press proof with a collision', 'report: tapping', 'report: tapping with --thread-proof',
    'report: thread proof with no hole measured', 'report: thread proof with --thread-tolerance',
    'report: thread proof of a hole not measured',
    'report: thread proof of a tap card the job does not know', 'report: a profile file',
    'report: a profile that differs from its named one', 'report: a resumed run');
  for (const which of ['condition units', 'press synchronisation', 'spindle synchronisation']) {
    tags.push(`state: ${which} absent`, `state: ${which} present`);
  }
  tags.push('state: a sync card waiting for its motion card', 'state: a deck from standard input');
  for (const name of schemas.profile.properties.base.enum) {
    tags.push(`profile: named ${name}`);
  }
  tags.push('profile: written by gen');
  for (const job of schemas.job.properties.job.enum) {
    tags.push(`job: ${job}`);
  }
  for (const command of schemas['json-output'].properties.command.enum) {
    tags.push(`json-output: command ${command}`);
  }
  for (const generator of jo.gen.properties.generator.enum) {
    if (generator === 'airfoil') {
      const branch = jo.gen.allOf.find((b) => b.if.properties.generator.const === 'airfoil');
      const jobs = branch.then.properties.job.enum;
      jobs.forEach((job) => tags.push(`json-output: gen airfoil ${job}`));
    } else {
      tags.push(`json-output: gen ${generator}`);
    }
  }
  for (const kind of ['motion', 'bad_punch', ...jo.show_card.else.then.properties.kind.enum]) {
    tags.push(`json-output: show card ${kind}`);
  }
  tags.push('json-output: show card with deck_errors', 'json-output: show card with warnings');
  for (const kind of jo.finding.properties.kind.enum) {
    tags.push(`json-output: check finding ${kind}`);
  }
  const limitKind = jo.finding.allOf.find((b) => b.then && b.then.properties && b.then.properties.limit_kind);
  for (const k of limitKind.then.properties.limit_kind.enum) {
    tags.push(`json-output: check limit_kind ${k}`);
  }
  return tags;
}

module.exports = { AXES, init, tag, requiredTags };
