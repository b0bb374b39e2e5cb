// The practice page in a SCORM package (raygrade export scorm): finds the LMS's API object,
// opens the session, gives the page the answers kept by the LMS (cmi.suspend_data) and sends
// the score after each Check. It runs before the page's own script, which uses it through
// window.raygradeLms; without an LMS (the page opened from a file or a plain web server) that
// is null and the page works as any practice page (docs/assignments.md, "SCORM").
"use strict";
window.raygradeLms = (function () {
  const data = JSON.parse(document.getElementById("handout-data").textContent);
  const version = data.practice && data.practice.scorm;
  if (!version) return null;
  const v12 = version !== "2004";

  // The API object is on a window above the page (the LMS's frames) or on the window that
  // opened it, as the SCORM run-time environment says. A frame of another origin cannot be
  // read: it is skipped. The bound only guards against a chain that never ends.
  const name = v12 ? "API" : "API_1484_11";
  function search(win) {
    for (let depth = 0; win && depth < 500; depth++) {
      try {
        if (win[name]) return win[name];
      } catch (e) { /* another origin */ }
      if (win.parent === win) break;
      win = win.parent;
    }
    return null;
  }
  const api = search(window) || (window.opener ? search(window.opener) : null);
  if (!api) return null;

  // The calls and the data model's names of each version.
  const call = v12
    ? {init: () => api.LMSInitialize(""), get: (k) => api.LMSGetValue(k), set: (k, v) => api.LMSSetValue(k, v),
       commit: () => api.LMSCommit(""), finish: () => api.LMSFinish(""), error: () => String(api.LMSGetLastError())}
    : {init: () => api.Initialize(""), get: (k) => api.GetValue(k), set: (k, v) => api.SetValue(k, v),
       commit: () => api.Commit(""), finish: () => api.Terminate(""), error: () => String(api.GetLastError())};
  const cmi = v12
    ? {learner: "cmi.core.student_id", raw: "cmi.core.score.raw", min: "cmi.core.score.min", max: "cmi.core.score.max",
       status: "cmi.core.lesson_status", exit: "cmi.core.exit"}
    : {learner: "cmi.learner_id", raw: "cmi.score.raw", min: "cmi.score.min", max: "cmi.score.max",
       status: "cmi.completion_status", exit: "cmi.exit"};
  // cmi.suspend_data holds at most 4096 characters in SCORM 1.2, 64000 in 2004.
  const limit = v12 ? 4096 : 64000;

  // A session opened already (the page reloaded by its Clear button) is taken over:
  // "already initialized" is error 101 in SCORM 1.2 and 103 in 2004.
  if (String(call.init()) !== "true" && call.error() !== (v12 ? "101" : "103")) return null;
  const text = (k) => { const v = call.get(k); return v === undefined || v === null ? "" : String(v); };
  const learner = text(cmi.learner);
  // Launched for the first time: the LMS shows the activity as begun.
  const begun = text(cmi.status);
  if (begun === "not attempted" || begun === "unknown" || begun === "") call.set(cmi.status, "incomplete");
  // Leaving the page suspends the attempt: the next launch resumes it with the same data.
  call.set(cmi.exit, "suspend");

  // The answers kept by the LMS, compactly: {"v": 1, "i": {problem: {input: value}},
  // "r": rows, "t": trees, "p": {problem: [attempts, full marks (1 or 0), score, max]}}.
  // Inputs are named "<problem>.<rest>": the problem's id is written once. Blank inputs and
  // boxes left unticked are not kept.
  const ids = data.problems.map((p) => p.id).sort((a, b) => b.length - a.length);
  function encode(state, progress) {
    const values = {};
    for (const [key, value] of Object.entries(state.values)) {
      if (value === "" || value === false) continue;
      const id = ids.find((p) => key.startsWith(p + ".")) || "";
      const rest = id ? key.slice(id.length + 1) : key;
      (values[id] = values[id] || {})[rest] = value === true ? 1 : value;
    }
    const out = {v: 1, i: values};
    const rows = {};
    for (const [key, n] of Object.entries(state.rows || {})) if (n > 1) rows[key] = n;
    if (Object.keys(rows).length) out.r = rows;
    if (Object.keys(state.trees || {}).length) out.t = state.trees;
    const p = {};
    for (const [id, q] of Object.entries(progress || {})) p[id] = [q.attempts, q.full ? 1 : 0, q.score || 0, q.max || 0];
    if (Object.keys(p).length) out.p = p;
    return JSON.stringify(out);
  }
  // What the LMS kept, read as untrusted: an older page wrote it, or anyone who can set
  // cmi.suspend_data. Only what has the shape this page writes is taken (answers as text or a
  // ticked box, row counts, trees as lists, progress as numbers); anything else is left out,
  // and data that is not this page's at all gives nothing, so that the page still opens and
  // reports. Progress an older page kept without a field takes its default.
  const plain = (o) => o !== null && typeof o === "object" && !Array.isArray(o);
  const number = (x) => (typeof x === "number" && Number.isFinite(x) ? x : 0);
  function decode(textValue) {
    let kept = null;
    try { kept = JSON.parse(textValue); } catch (e) { return null; }
    if (!plain(kept) || kept.v !== 1 || !plain(kept.i)) return null;
    // Objects without a prototype: a key "__proto__" is a key like any other.
    const values = Object.create(null), rows = Object.create(null), trees = Object.create(null);
    const progress = Object.create(null);
    for (const [id, inputs] of Object.entries(kept.i)) {
      if (!plain(inputs)) continue;
      for (const [rest, value] of Object.entries(inputs)) {
        if (typeof value !== "string" && value !== 1) continue;
        values[id ? id + "." + rest : rest] = value === 1 ? true : value;
      }
    }
    // A page adds at most a few hundred rows; more is not this page's data.
    for (const [key, n] of Object.entries(plain(kept.r) ? kept.r : {})) {
      if (Number.isInteger(n) && n > 0 && n <= 1000) rows[key] = n;
    }
    for (const [key, t] of Object.entries(plain(kept.t) ? kept.t : {})) if (Array.isArray(t)) trees[key] = t;
    for (const [id, q] of Object.entries(plain(kept.p) ? kept.p : {})) {
      if (!Array.isArray(q)) continue;
      const attempts = Number.isInteger(q[0]) && q[0] >= 0 ? q[0] : 0;
      progress[id] = {attempts: attempts, full: q[1] === 1 || q[1] === true, score: number(q[2]), max: number(q[3])};
    }
    return {values: values, rows: rows, trees: trees, progress: progress};
  }
  const resumed = decode(text("cmi.suspend_data"));

  let open = true;
  let keepOpen = false;
  window.addEventListener("pagehide", () => {
    if (!open || keepOpen) return;
    open = false;
    call.finish();
  });
  const lms = {
    version: version,
    learner: learner,
    resumed: resumed,
    // Keeps the answers in cmi.suspend_data (sent with the next commit); returns what to tell
    // the student. Answers too long for the LMS stay in this browser only, and the LMS keeps
    // what it had.
    save: (state, progress) => {
      if (!open) return "Saved in this browser only: the connection to your course's site has ended.";
      const kept = encode(state, progress);
      if (kept.length > limit) {
        return "Saved in this browser only: your answers take " + kept.length + " characters, more than the " +
          limit + " your course's site keeps for this activity.";
      }
      if (String(call.set("cmi.suspend_data", kept)) === "true") return "Saved in this browser and on your course's site.";
      return "Saved in this browser only: your course's site refused the answers (error " + call.error() + ").";
    },
    // The score on the whole assignment (points of maxPoints) as a percentage; passed when
    // every problem's last Check earned all its points, else incomplete (attempts never run
    // out). Sent at once (a commit).
    report: (points, maxPoints, passed) => {
      if (!open) return false;
      const raw = maxPoints > 0 ? Math.round(10000 * Math.min(points, maxPoints) / maxPoints) / 100 : 0;
      call.set(cmi.min, "0");
      call.set(cmi.max, "100");
      call.set(cmi.raw, String(raw));
      if (v12) {
        call.set(cmi.status, passed ? "passed" : "incomplete");
      } else {
        call.set("cmi.score.scaled", String(raw / 100));
        call.set(cmi.status, passed ? "completed" : "incomplete");
        call.set("cmi.success_status", passed ? "passed" : "unknown");
      }
      return String(call.commit()) === "true";
    },
    // The Clear button: the LMS forgets the answers; the session stays open for the page that
    // reloads.
    clear: () => {
      if (!open) return;
      call.set("cmi.suspend_data", "");
      call.commit();
      keepOpen = true;
    },
  };
  return lms;
})();
