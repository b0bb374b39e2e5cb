// raygrade.js against the native raygrade, byte for byte: every file of the bundled bank
// solved (answers as JSON, and the worked solution in md, html and txt), the whole bank at
// once, every sample submission graded against the whole bank, and the accuracy study's hard
// cases (which need the precision ladder's top, SoftFloat in the browser, MPFR natively) as
// one bank; the example assignment's worked solutions and grades. The standard error lines and
// exit codes are compared too.
// Usage: node tests/web_node_test.js RAYGRADE_JS NATIVE_RAYGRADE SOURCE_DIR [K/N]
// With K/N (0 <= K < N), only every Nth comparison from the Kth is made, so N processes side by
// side make them all.
'use strict';
const fs = require('fs');
const os = require('os');
const path = require('path');
const {spawnSync} = require('child_process');

const [raygradeJs, native, sourceDir, share = '0/1'] = process.argv.slice(2);
const [shard, shards] = share.split('/').map(Number);
if (!sourceDir || !(shards >= 1 && shard >= 0 && shard < shards)) {
  console.error('usage: node web_node_test.js RAYGRADE_JS NATIVE_RAYGRADE SOURCE_DIR [K/N]');
  process.exit(2);
}
// Whether this process makes the next comparison.
let next = 0;
const mine = () => next++ % shards === shard;
process.chdir(sourceDir);

// The .json files under `folder`, in the order raygrade lists a folder (sorted paths).
function jsonFiles(folder) {
  const out = [];
  for (const entry of fs.readdirSync(folder, {withFileTypes: true})) {
    const p = path.join(folder, entry.name);
    if (entry.isDirectory()) out.push(...jsonFiles(p));
    else if (entry.name.endsWith('.json')) out.push(p);
  }
  return out.sort();
}

function runNative(args, cwd = '.') {
  const r = spawnSync(path.resolve(native), args, {encoding: 'utf8', maxBuffer: 1 << 30, cwd});
  if (r.error) throw r.error;
  const errors = r.stderr.split('\n').filter((line) => line !== '');
  return {out: r.stdout, errors, status: r.status};
}

let failures = 0, compared = 0;
function compare(what, web, errors, status, expected) {
  ++compared;
  const problems = [];
  if (web !== expected.out) {
    let i = 0;
    while (i < web.length && web[i] === expected.out[i]) ++i;
    problems.push(`output differs at byte ${i}: native ${JSON.stringify(expected.out.slice(i, i + 80))}` +
                  `, raygrade.js ${JSON.stringify(web.slice(i, i + 80))}`);
  }
  if (JSON.stringify(errors) !== JSON.stringify(expected.errors)) {
    problems.push(`standard error: native ${JSON.stringify(expected.errors)}, raygrade.js ${JSON.stringify(errors)}`);
  }
  if (status !== expected.status) problems.push(`exit code: native ${expected.status}, raygrade.js ${status}`);
  if (problems.length) {
    ++failures;
    console.log(`FAIL ${what}\n  ${problems.join('\n  ')}`);
  }
}

require(path.resolve(raygradeJs))().then((raygrade) => {
  const bank = jsonFiles('problems');
  const texts = {};
  for (const f of bank) texts[f] = fs.readFileSync(f, 'utf8');
  const one = (f) => ({[f]: texts[f]});

  // Each file: the answers, and the worked solution in every format.
  for (const f of bank) {
    if (mine()) compare(`solve ${f}`, raygrade.solve(one(f)), raygrade.lastErrors(), raygrade.lastStatus(),
            runNative(['solve', f, '--format', 'json']));
    for (const format of ['md', 'html', 'txt']) {
      if (!mine()) continue;
      compare(`solve ${f} --format ${format}`, raygrade.solution(one(f), format),
              raygrade.lastErrors(), raygrade.lastStatus(),
              runNative(['solve', f, '--format', format]));
    }
  }
  // The whole bank at once.
  if (mine()) compare('solve problems', raygrade.solve(texts), raygrade.lastErrors(), raygrade.lastStatus(),
          runNative(['solve', 'problems', '--format', 'json']));
  // Every sample submission against the whole bank.
  for (const s of jsonFiles('submissions')) {
    if (!mine()) continue;
    const web = raygrade.grade(texts, fs.readFileSync(s, 'utf8'), s);
    compare(`grade ${s}`, web, raygrade.lastErrors(), raygrade.lastStatus(),
            runNative(['grade', '--problems', 'problems', '--format', 'json', s]));
  }
  // The example assignment: one student's worked solutions, and every sample submission graded
  // as that assignment's (before and after its due date, the second time from the cache).
  const assignment = 'assignments/homework-rays.json';
  const withAssignment = Object.assign({[assignment]: fs.readFileSync(assignment, 'utf8')}, texts);
  for (const format of ['json', 'html']) {
    if (!mine()) continue;
    compare(`solve ${assignment} --student s001 --format ${format}`,
            raygrade.solveAssignment(withAssignment, assignment, 's001', format),
            raygrade.lastErrors(), raygrade.lastStatus(),
            runNative(['solve', assignment, '--student', 's001', '--format', format]));
  }
  for (const when of ['2026-11-24T00:00:00Z', '2026-12-24T00:00:00Z']) {
    for (const s of jsonFiles('submissions')) {
      for (const cacheKey of ['', 'example']) {
        if (!mine()) continue;
        const web = raygrade.gradeAssignment(withAssignment, assignment, fs.readFileSync(s, 'utf8'),
                                             {now: Date.parse(when) / 1000, submissionName: s, cacheKey});
        compare(`grade --assignment --now ${when} ${s} (cache key "${cacheKey}")`, web,
                raygrade.lastErrors(), raygrade.lastStatus(),
                runNative(['grade', '--assignment', assignment, '--now', when, '--format', 'json', s]));
      }
    }
  }
  // The hard cases, where the answer needs double-double, the top of the ladder or an exact
  // decision on a boundary; and a problem file with a fault, for the diagnostics.
  // The hard cases in two halves (every other problem), so two processes share them.
  const levels = {};
  for (const half of [0, 1]) {
    if (!mine()) continue;
    const scratch = fs.mkdtempSync(path.join(os.tmpdir(), 'raygrade-web-'));
    const all = path.join(scratch, 'hard-cases.json');
    // The accuracy study's hard cases as one bank of intersect problems, posed by the native
    // raygrade itself (each primitive writes its own object), so no primitive is left out.
    const posed = runNative(['bench', '--corpus-problems', all]);
    if (posed.status !== 0) throw new Error(`raygrade bench --corpus-problems: ${posed.errors.join('; ')}`);
    const bankOfAll = JSON.parse(fs.readFileSync(all, 'utf8'));
    bankOfAll.problems = bankOfAll.problems.filter((_, i) => i % 2 === half);
    const hard = path.join(scratch, `hard-cases-${half}.json`);
    fs.writeFileSync(hard, JSON.stringify(bankOfAll, null, 2) + '\n');
    const web = raygrade.solve({[hard.slice(1)]: fs.readFileSync(hard, 'utf8')});
    compare(`solve hard cases (half ${half})`, web, raygrade.lastErrors(), raygrade.lastStatus(),
            runNative(['solve', hard.slice(1), '--format', 'json'], '/'));
    for (const s of JSON.parse(web).solutions) {
      // No level: an object the study has no case for (a cone whose apex − base is not exactly
      // h·â once written as a problem), answered in double.
      const level = s.level || 'none';
      levels[level] = (levels[level] || 0) + 1;
    }
    fs.rmSync(scratch, {recursive: true});
  }
  if (mine()) {
    const broken = '{"problems": [{"id": "p", "kind": "intersect", "ray": {"origin": [0, 0, 0],\n' +
                   '  "direction": [0, 0, 0]}, "object": {"type": "sphere", "radius": 1}, "colour": 1}]}';
    const brokenFile = path.join(fs.mkdtempSync(path.join(os.tmpdir(), 'raygrade-web-')), 'broken.json');
    fs.writeFileSync(brokenFile, broken);
    compare('solve a faulty file', raygrade.solve({[brokenFile.slice(1)]: broken}),
            raygrade.lastErrors(), raygrade.lastStatus(),
            runNative(['solve', brokenFile.slice(1), '--format', 'json'], '/'));
    fs.rmSync(path.dirname(brokenFile), {recursive: true});
  }
  // Misuse of the API is an error that says what is wrong, never silently ignored.
  const refused = (what, call, words) => {
    ++compared;
    try {
      call();
    } catch (e) {
      if (String(e.message).includes(words)) return;
      console.log(`FAIL ${what}: the error says ${JSON.stringify(e.message)}`);
      ++failures;
      return;
    }
    console.log(`FAIL ${what}: no error`);
    ++failures;
  };
  if (mine()) {
    refused('an unknown option', () => raygrade.gradeAssignment(withAssignment, assignment, '{}',
                                                               {cachekey: 'x'}), 'unknown option "cachekey"');
    refused('a file name outside the folder', () => raygrade.solve({'../p.json': '{}'}), 'must be relative');
    refused('an unknown format', () => raygrade.solution(texts[bank[0]], 'pdf'), 'unknown format "pdf"');
  }
  if (Object.keys(levels).length) console.log(`hard cases by level: ${JSON.stringify(levels)}`);
  console.log(`${compared - failures} of ${compared} outputs identical`);
  process.exit(failures ? 1 : 0);
}).catch((e) => {
  console.error(e);
  process.exit(1);
});
