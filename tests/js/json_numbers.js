// The numbers of a JSON text as parsons writes them (docs/report.md, "Figures are rounded to
// what they resolve"), read from the text itself, not from the parsed values:
//   - every number is the shortest text that reads back to its double (JavaScript's own
//     Number-to-string is that shortest text), so 336.91522200000003 for 336.915222 fails;
//     the fixed six decimals of the events' times ("0.020800") count without trailing zeros;
//   - in a report, an events line or a --json document, no figure has more decimals than its
//     kind is rounded to: lengths (keys ending _in, and the axes' positions) 0.00001 in (the
//     thread proof's 0.000001 in), angles (_deg) 0.0001 degree, everything else (times to the
//     microsecond, ratios) six decimals.
//     Saved states, profiles and job files are read back by parsons and keep every bit, as does
//     the profile a report quotes (profile_applied).
// numberFindings(text, schema) returns one line per number that breaks either rule.
'use strict';

const ROUNDED = new Set(['report', 'events', 'json-output']);
const KEPT_UNDER = new Set(['profile_applied']); // a profile's values, every bit
const POSITIONS = new Set(['position', 'real_position', 'position_error', 'screw_slip',
  'screw_turns_position', 'screw_turns_minus_position']);
// The thread proof's lengths: to the microinch, a pitch error being tens of microinches.
const MICROINCH = new Set(['surface_in', 'thread_depth_in', 'full_thread_in', 'mean_pitch_in',
  'worst_pitch_in']);

function places(key) {
  if (MICROINCH.has(key)) {
    return 6;
  }
  if (key.endsWith('_in') || POSITIONS.has(key)) {
    return 5;
  }
  if (key.endsWith('_deg')) {
    return 4;
  }
  return 6;
}

// Digits after the point, the exponent counted in ("6e-05": 5), trailing zeros left out.
function decimalsOf(literal) {
  const m = /^-?\d+(?:\.(\d*?)0*)?(?:[eE]([-+]?\d+))?$/.exec(literal);
  if (!m) {
    return 0;
  }
  return Math.max(0, (m[1] || '').length - Number(m[2] || 0));
}

// Significant digits, leading and trailing zeros left out.
function significantDigits(literal) {
  const mantissa = literal.replace(/^-/, '').split(/[eE]/)[0].replace('.', '');
  return mantissa.replace(/^0+/, '').replace(/0+$/, '').length;
}

function numberFindings(text, schema) {
  const findings = [];
  const rounded = ROUNDED.has(schema);
  const stack = []; // one entry per open object or array: {key, kept}
  let key = ''; // the key whose value comes next, in the innermost object
  let i = 0;
  const top = () => stack[stack.length - 1];
  const here = () => (top() && top().array ? top().key : key);
  while (i < text.length) {
    const c = text[i];
    if (c === '"') {
      let j = i + 1;
      while (text[j] !== '"') {
        j += text[j] === '\\' ? 2 : 1;
      }
      const str = JSON.parse(text.slice(i, j + 1));
      let k = j + 1;
      while (/\s/.test(text[k] || '')) {
        k += 1;
      }
      if (text[k] === ':') {
        key = str;
      }
      i = j + 1;
    } else if (c === '{' || c === '[') {
      const name = here();
      const kept = (top() ? top().kept : false) || KEPT_UNDER.has(name);
      stack.push({ key: name, kept, array: c === '[', outer: key });
      key = '';
      i += 1;
    } else if (c === '}' || c === ']') {
      key = stack.pop().outer;
      i += 1;
    } else if (c === '-' || (c >= '0' && c <= '9')) {
      const m = /^-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?/.exec(text.slice(i, i + 64));
      const literal = m[0];
      const name = here();
      const shortest = String(Number(literal));
      if (significantDigits(literal) > significantDigits(shortest)) {
        findings.push(`${name}: ${literal} is not the shortest text of its value (${shortest})`);
      }
      const kept = top() ? top().kept : false;
      if (rounded && !kept && decimalsOf(literal) > places(name)) {
        findings.push(`${name}: ${literal} has more than the ${places(name)} decimals its ` +
                      'kind is rounded to');
      }
      i += literal.length;
    } else {
      i += 1;
    }
  }
  return findings;
}

// The numbers' rule must be able to fail: float noise, too many decimals for the kind, and a
// figure under the report's quoted profile (kept to the last bit, so it passes). `fail` reports
// a case that went wrong; the count of such cases is returned.
function numberSelfCheck(fail) {
  const cases = [
    ['report', '{"machine_seconds": 88.19411099999999}', 1],
    ['report', '{"cards": [{"start_seconds": 336.91522200000003}]}', 2], // both rules
    ['report', '{"axes": {"table": {"real_position": 0.123456}}}', 1],
    ['json-output', '{"moves": [{"degrees": 32.05128205128205}]}', 1],
    ['report', '{"press": {"cycle_clearance_in": [0.09312899999999999, 0.1]}}', 1],
    ['report', '{"machine_seconds": 88.194111, "profile_applied": {"x_deg": 332.2130851211906}}', 0],
    ['profile', '{"press": {"start_angle_deg": 332.2130851211906}}', 0],
    ['state', '{"t": 0.30000000000000004}', 0],
    ['job', '{"t": 0.10000000000000001}', 1],
    ['events', '{"t":0.020800,"signal":"a 0.30000000000000004 b"}', 0],
  ];
  let wrong = 0;
  for (const [schema, text, expected] of cases) {
    const found = numberFindings(text, schema).length;
    if (found !== expected) {
      wrong += 1;
      fail(`numbers' rule: ${schema} ${text}: ${found} finding(s), expected ${expected}`);
    } else {
      console.log(`ok    numbers' rule: ${schema} ${text}: ${found} finding(s)`);
    }
  }
  return wrong;
}

module.exports = { numberFindings, numberSelfCheck, decimalsOf, significantDigits };
