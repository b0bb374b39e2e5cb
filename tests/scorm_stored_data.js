// The SCORM page's LMS script (grader/assignments/platforms/scorm_page.js) given hostile or old
// cmi.suspend_data, run in Node with a stand-in SCORM 1.2 API object: whatever the LMS keeps,
// the script opens the session, hands the page answers of the shapes it reads (or none), and
// sends the score. Usage: node scorm_stored_data.js REPOSITORY
"use strict";
const fs = require("fs");
const path = require("path");
const vm = require("vm");

const source = fs.readFileSync(path.join(process.argv[2], "grader/assignments/platforms/scorm_page.js"), "utf8");
const failures = [];
const check = (ok, message) => { if (!ok) { failures.push(message); console.log("FAIL: " + message); } };

// Runs the script once against an LMS that holds `suspend` as cmi.suspend_data.
function launch(suspend) {
  const store = {"cmi.suspend_data": suspend, "cmi.core.lesson_status": "incomplete",
                 "cmi.core.student_id": "s1"};
  const api = {
    LMSInitialize: () => "true",
    LMSGetValue: (k) => (k in store ? store[k] : ""),
    LMSSetValue: (k, v) => { store[k] = v; return "true"; },
    LMSCommit: () => "true",
    LMSFinish: () => "true",
    LMSGetLastError: () => 0,
  };
  const data = {practice: {scorm: "1.2"}, problems: [{id: "p1"}, {id: "p1.b"}]};
  const win = {API: api, opener: null, addEventListener: () => {}};
  win.parent = win;
  const document = {getElementById: (id) => (id === "handout-data" ? {textContent: JSON.stringify(data)} : null)};
  const context = vm.createContext({window: win, document: document});
  let thrown = null;
  try { vm.runInContext(source, context); } catch (e) { thrown = e; }
  return {lms: win.raygradeLms, store: store, thrown: thrown};
}

const plain = (o) => o !== null && typeof o === "object" && !Array.isArray(o);
const finite = (x) => typeof x === "number" && Number.isFinite(x);

// What the page reads of resumed answers (handout_page.js: restore and practice).
function wellTyped(r, where) {
  if (r === null) return;
  check(plain(r), where + ": resumed is not an object");
  if (!plain(r)) return;
  check(plain(r.values) && Object.values(r.values).every((v) => typeof v === "string" || v === true),
        where + ": values " + JSON.stringify(r.values));
  check(plain(r.rows) && Object.values(r.rows).every((n) => Number.isInteger(n) && n > 0 && n <= 1000),
        where + ": rows " + JSON.stringify(r.rows));
  check(plain(r.trees) && Object.values(r.trees).every(Array.isArray),
        where + ": trees " + JSON.stringify(r.trees));
  check(plain(r.progress), where + ": progress " + JSON.stringify(r.progress));
  for (const [id, p] of Object.entries(r.progress || {})) {
    check(plain(p) && Number.isInteger(p.attempts) && p.attempts >= 0 && typeof p.full === "boolean" &&
          finite(p.score) && finite(p.max), where + ": progress of " + id + " " + JSON.stringify(p));
  }
  // The script's objects come from its own realm: their prototype is that realm's
  // Object.prototype (whose prototype is null), or null; never one the data gave.
  const proto = Object.getPrototypeOf(r.values);
  check(proto === null || Object.getPrototypeOf(proto) === null, where + ": values' prototype was replaced");
}

const hostile = [
  '{"v":1,"i":{"x":null}}',  // the report's case: Object.entries(null) threw
  '{"v":1,"i":null}', '{"v":1,"i":[1,2]}', '{"v":1,"i":"text"}', '{"v":1,"i":{"p1":5}}',
  '{"v":1,"i":{"p1":{"a":{"deep":1}}}}', '{"v":1,"i":{"p1":{"a":[1]}}}', '{"v":1,"i":{"p1":{"a":null}}}',
  '{"v":1,"i":{"__proto__":{"a":"1"}}}', '{"v":1,"i":{"":{"__proto__":{"polluted":"1"}}}}', '{"v":1,"i":{"p1":{"__proto__":"x"}}}',
  '{"v":1,"i":{},"p":null}', '{"v":1,"i":{},"p":[1]}', '{"v":1,"i":{},"p":{"p1":null}}',
  '{"v":1,"i":{},"p":{"p1":"xx"}}', '{"v":1,"i":{},"p":{"p1":[1e999,"a",{},-3]}}',
  '{"v":1,"i":{},"p":{"p1":{"0":1}}}', '{"v":1,"i":{},"r":"x","t":5}', '{"v":1,"i":{},"r":{"p1.h":1e9}}',
  '{"v":1,"i":{},"r":{"p1.h":"3"},"t":{"p1.0":{"a":1}}}', '{"v":2,"i":{}}', '{"v":1}',
  'null', '[]', '1', '"text"', 'true', '', '{', '\u0000', '{"v":1,"i":{"p1":{"a":"' + "x".repeat(100000) + '"}}}',
  "[".repeat(100000) + "]".repeat(100000),
];
for (const suspend of hostile) {
  const where = "suspend_data " + JSON.stringify(suspend.slice(0, 60));
  const run = launch(suspend);
  check(run.thrown === null, where + ": the script threw " + run.thrown);
  check(run.lms !== null && typeof run.lms === "object", where + ": no LMS link (window.raygradeLms " + run.lms + ")");
  if (!run.lms) continue;
  wellTyped(run.lms.resumed, where);
  check(run.lms.report(1, 4, false) === true && run.store["cmi.core.score.raw"] === "25",
        where + ": the score sent is " + run.store["cmi.core.score.raw"] + ", not 25");
}

// Data an older page kept: progress without the score and maximum ([attempts, full]), or
// without full marks ([attempts]): each missing field takes its default.
{
  const run = launch('{"v":1,"i":{"p1":{"t":"2"}},"p":{"p1":[3,1],"p1.b":[2]}}');
  const r = run.lms && run.lms.resumed;
  check(r && r.values["p1.t"] === "2", "older data: the answer p1.t is not resumed: " + JSON.stringify(r));
  check(r && JSON.stringify(r.progress["p1"]) === '{"attempts":3,"full":true,"score":0,"max":0}',
        "older data: p1's progress " + JSON.stringify(r && r.progress["p1"]));
  check(r && JSON.stringify(r.progress["p1.b"]) === '{"attempts":2,"full":false,"score":0,"max":0}',
        "older data: p1.b's progress " + JSON.stringify(r && r.progress["p1.b"]));
}

// What this page writes reads back the same (a problem id with a dot, a ticked box, rows).
{
  const kept = '{"v":1,"i":{"p1":{"t":"2.5","ok":1},"p1.b":{"hits.0.t":"1"}},"r":{"p1.hits":2},' +
               '"t":{"p1.b.0":[{"kind":"reflect"}]},"p":{"p1":[2,0,1.5,2]}}';
  const r = launch(kept).lms.resumed;
  check(JSON.stringify(r) === JSON.stringify({
    values: {"p1.t": "2.5", "p1.ok": true, "p1.b.hits.0.t": "1"}, rows: {"p1.hits": 2},
    trees: {"p1.b.0": [{kind: "reflect"}]}, progress: {p1: {attempts: 2, full: false, score: 1.5, max: 2}}}),
  "well-formed data reads back as " + JSON.stringify(r));
}

console.log(failures.length ? failures.length + " failures" : "SCORM stored data: ok");
process.exit(failures.length ? 1 : 0);
