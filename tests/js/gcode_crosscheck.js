// The G-code round trip, checked by an independent interpreter (docs/gcode.md):
//
//   PROGRAM.ngc --parsons gen gcode--> deck --parsons run--> path.csv (the emulated path)
//                                          --parsons convert--> path.ngc (the path as G-code)
//
// gcode-toolpath (npm, cncjs's interpreter; tests/js/package-lock.json pins it) reads both the
// program and parsons's path.ngc. Asserted:
//   1. the path it reads from path.ngc, after the cards that bring the machine to the work
//      zero, stays within the tolerance of the program's own path as it reads it (every point
//      of one within the tolerance of the other, both ways);
//   2. the path it reads from path.ngc is the emulated path: every row of path.csv lies within
//      the G-code writer's 0.0001 in of it, and every point it reads is a row of path.csv;
//   3. it sees as many arcs in the program as parsons says it read.
//
//   node gcode_crosscheck.js PARSONS_EXE PROGRAM.ngc WORK_DIR
// Exit 0 when all hold; 1 with the figures when one does not.
'use strict';

const fs = require('fs');
const path = require('path');
const { spawnSync } = require('child_process');
const Toolpath = require('gcode-toolpath');

const [exeArg, program, work] = process.argv.slice(2);
const exe = exeArg && path.resolve(exeArg);
if (!exeArg || !program || !work) {
    console.error('usage: node gcode_crosscheck.js PARSONS_EXE PROGRAM.ngc WORK_DIR');
    process.exit(2);
}
fs.mkdirSync(work, { recursive: true });
const MM = 25.4;
const WRITER_TOLERANCE_IN = 0.0001; // outputs/traces/gcode_path.hpp
const PRINTED_IN = 0.000006; // 5 decimals on both sides

function parsons(args, expected = 0) {
    const r = spawnSync(exe, args, { cwd: work, encoding: 'utf8' });
    if (r.status !== expected) {
        console.error(`parsons ${args.join(' ')}: exit ${r.status}, not ${expected}\n${r.stderr}`);
        process.exit(1);
    }
    return r.stdout;
}

// The moves gcode-toolpath reads from a G-code text, in inches: lines [v1, v2] and arcs.
function interpret(text) {
    const moves = [];
    const inches = (v) => ({ x: v.x / MM, y: v.y / MM, z: v.z / MM });
    const toolpath = new Toolpath({
        addLine: (modal, v1, v2) => moves.push({ kind: 'line', v1: inches(v1), v2: inches(v2) }),
        addArcCurve: (modal, v1, v2, v0) =>
            moves.push({ kind: 'arc', cw: modal.motion === 'G2', v1: inches(v1), v2: inches(v2),
                         v0: inches(v0) }),
    });
    toolpath.loadFromStringSync(text);
    return moves;
}

// A move as a polyline of points no more than `step` inches apart (arcs: chords of that
// length, whose sagitta is step^2 / 8r, far under a millionth of an inch).
function polyline(moves, step) {
    const pts = [];
    for (const m of moves) {
        if (pts.length === 0) pts.push([m.v1.x, m.v1.y, m.v1.z]);
        if (m.kind === 'line') {
            pts.push([m.v2.x, m.v2.y, m.v2.z]);
            continue;
        }
        const a0 = Math.atan2(m.v1.y - m.v0.y, m.v1.x - m.v0.x);
        const a1 = Math.atan2(m.v2.y - m.v0.y, m.v2.x - m.v0.x);
        const r0 = Math.hypot(m.v1.x - m.v0.x, m.v1.y - m.v0.y);
        const r1 = Math.hypot(m.v2.x - m.v0.x, m.v2.y - m.v0.y);
        let sweep = a1 - a0;
        if (m.cw) { while (sweep >= -1e-12) sweep -= 2 * Math.PI; }
        else { while (sweep <= 1e-12) sweep += 2 * Math.PI; }
        const n = Math.max(1, Math.ceil(Math.abs(sweep) * Math.max(r0, r1) / step));
        for (let i = 1; i <= n; i++) {
            const f = i / n;
            const r = r0 + f * (r1 - r0);
            const a = a0 + f * sweep;
            pts.push(i === n ? [m.v2.x, m.v2.y, m.v2.z]
                             : [m.v0.x + r * Math.cos(a), m.v0.y + r * Math.sin(a),
                                m.v1.z + f * (m.v2.z - m.v1.z)]);
        }
    }
    return pts;
}

function segDistance(p, a, b) {
    const d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    const len2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    let t = len2 === 0 ? 0 : ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1] + (p[2] - a[2]) * d[2]) / len2;
    t = Math.max(0, Math.min(1, t));
    return Math.hypot(p[0] - a[0] - t * d[0], p[1] - a[1] - t * d[1], p[2] - a[2] - t * d[2]);
}

// The segments of a polyline in a grid of cells `cell` inches wide, for the distance from a
// point to the polyline where that distance is under `cell`.
class SegmentGrid {
    constructor(pts, cell) {
        this.pts = pts;
        this.cell = cell;
        this.cells = new Map();
        for (let i = 0; i + 1 < pts.length; i++) {
            const lo = [0, 1, 2].map((k) => Math.floor(Math.min(pts[i][k], pts[i + 1][k]) / cell));
            const hi = [0, 1, 2].map((k) => Math.floor(Math.max(pts[i][k], pts[i + 1][k]) / cell));
            for (let x = lo[0]; x <= hi[0]; x++)
                for (let y = lo[1]; y <= hi[1]; y++)
                    for (let z = lo[2]; z <= hi[2]; z++) {
                        const key = `${x},${y},${z}`;
                        if (!this.cells.has(key)) this.cells.set(key, []);
                        this.cells.get(key).push(i);
                    }
        }
    }
    distance(p) {
        const c = p.map((v) => Math.floor(v / this.cell));
        let best = Infinity;
        for (let x = c[0] - 1; x <= c[0] + 1; x++)
            for (let y = c[1] - 1; y <= c[1] + 1; y++)
                for (let z = c[2] - 1; z <= c[2] + 1; z++) {
                    for (const i of this.cells.get(`${x},${y},${z}`) || []) {
                        best = Math.min(best, segDistance(p, this.pts[i], this.pts[i + 1]));
                    }
                }
        return best; // Infinity: further than a cell
    }
}

// Points along a polyline no more than `step` apart, the vertices among them.
function samples(pts, step) {
    const out = [];
    for (let i = 0; i + 1 < pts.length; i++) {
        const a = pts[i];
        const b = pts[i + 1];
        const n = Math.max(1, Math.ceil(Math.hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]) / step));
        for (let k = 0; k < n; k++) {
            const f = k / n;
            out.push([a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])]);
        }
    }
    if (pts.length) out.push(pts[pts.length - 1]);
    return out;
}

function worst(points, grid) {
    let max = 0;
    let at = null;
    for (const p of points) {
        const d = grid.distance(p);
        if (d > max) { max = d; at = p; }
    }
    return { max, at };
}

const fmtPoint = (p) => (p ? `(${p.map((v) => v.toFixed(5)).join(', ')})` : '-');
let failed = false;
function check(what, value, limit) {
    const ok = value <= limit;
    console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}: ${value === Infinity ? 'more than a cell' : value.toFixed(6)} in (limit ${limit.toFixed(6)} in)`);
    if (!ok) failed = true;
}

// 1. The deck, the emulated path and the path as G-code.
const name = path.basename(program, path.extname(program));
const gen = JSON.parse(parsons(['gen', 'gcode', path.resolve(program), '-o', `${name}.cbn`, '--json']));
parsons(['run', `${name}.cbn`, '--path', `${name}.path.csv`, '-q']);
parsons(['convert', `${name}.cbn`, '-o', `${name}.path.ngc`]);
const tolerance = gen.tolerance_in;
const zero = gen.work_zero_in;
console.log(`${program}: ${gen.cards} cards (${gen.approach_cards} to the work zero), ${gen.lines} lines and ${gen.arcs} arcs, work zero ${zero.join(', ')} in, tolerance ${tolerance} in`);

// 2. What the independent interpreter reads.
const programMoves = interpret(fs.readFileSync(program, 'utf8'));
const arcsSeen = programMoves.filter((m) => m.kind === 'arc').length;
if (arcsSeen !== gen.arcs) {
    console.error(`FAIL gcode-toolpath reads ${arcsSeen} arcs in ${program}, parsons ${gen.arcs}`);
    failed = true;
}
const ngc = fs.readFileSync(path.join(work, `${name}.path.ngc`), 'utf8');
const pathMoves = interpret(ngc);
if (pathMoves.some((m) => m.kind !== 'line')) {
    console.error('FAIL parsons wrote something other than straight lines');
    failed = true;
}
// The lines before the first card of the program proper bring the machine to the work zero.
const lines = ngc.split('\n');
const firstCard = lines.findIndex((l) => l.startsWith(`(card ${gen.approach_cards + 1},`));
const approachMoves = lines.slice(0, firstCard).filter((l) => /^G1 /.test(l)).length;
const machinePath = polyline(pathMoves, 1);
const cutPath = machinePath.slice(approachMoves).map((p) => [p[0] - zero[0], p[1] - zero[1], p[2] - zero[2]]);
const programPath = polyline(programMoves, 0.001);
console.log(`gcode-toolpath: ${programMoves.length} moves in the program (${arcsSeen} arcs), ${pathMoves.length} lines in parsons's path (${approachMoves} to the work zero)`);

// 3. Within the tolerance of the program, both ways.
const cell = Math.max(0.02, 2 * tolerance);
const fromCut = worst(samples(cutPath, 0.0005), new SegmentGrid(programPath, cell));
check(`the path as cut, off the program's path (worst at ${fmtPoint(fromCut.at)})`, fromCut.max, tolerance);
const fromProgram = worst(samples(programPath, 0.0005), new SegmentGrid(cutPath, cell));
check(`the program's path, off the path as cut (worst at ${fmtPoint(fromProgram.at)})`, fromProgram.max, tolerance);

// 4. The G-code is the emulated path.
const rows = fs.readFileSync(path.join(work, `${name}.path.csv`), 'utf8').trim().split('\n').slice(1)
    .map((l) => l.split(',').slice(1, 4).map(Number));
const emulated = [[0, 0, 0], ...rows];
const rowsOff = worst(emulated, new SegmentGrid(machinePath, 0.01));
check(`path.csv's ${rows.length} rows, off the G-code's path (worst at ${fmtPoint(rowsOff.at)})`, rowsOff.max, WRITER_TOLERANCE_IN + PRINTED_IN);
const verticesOff = worst(machinePath, new SegmentGrid(emulated, 0.01));
check(`the G-code's ${machinePath.length} points, off path.csv (worst at ${fmtPoint(verticesOff.at)})`, verticesOff.max, PRINTED_IN);

process.exit(failed ? 1 : 0);
