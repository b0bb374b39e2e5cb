// The handout page: answer inputs built from each problem's form, typed numbers read as the
// grader reads them, progress kept in the browser, and answers.json downloaded in the
// submission format. Nothing is sent anywhere.
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("handout-data").textContent);
  const storageKey = "raygrade:" + data.assignment.id + ":" + (data.student.key || "");

  // --- Typed numbers and formulas, read with the grammar of the grader (docs/submission-format.md)
  const GLYPHS = {"\u2212": "-", "\u00b7": "*", "\u22c5": "*", "\u00d7": "*", "\u00f7": "/",
                  "\u00b2": "\u00b2", "\u00b3": "\u00b3", "\u221a": "\u221a", "\u03c0": "\u03c0"};
  const FUNCS = {};
  for (const f of data.formula.functions) FUNCS[f] = true;
  const MAX_LENGTH = data.formula.max_length, MAX_DEPTH = data.formula.max_depth;

  function readFormula(text, symbols) {
    const chars = Array.from(text).map((c) => GLYPHS[c] || c);
    let pos = 0, failed = null;
    const known = {};
    for (const s of symbols || []) known[s] = true;
    const fail = (message) => { if (!failed) failed = {message: message, column: pos + 1}; return NaN; };
    const peek = () => (pos < chars.length ? chars[pos] : "");
    const space = () => { while (peek() === " " || peek() === "\t") pos++; };
    const isAlpha = (c) => /^[A-Za-z_]$/.test(c);
    const isDigit = (c) => /^[0-9]$/.test(c);
    const startsPrimary = (c) => c === "(" || c === "\u221a" || c === "\u03c0" || isAlpha(c);
    const enter = (depth) => {
      if (depth > MAX_DEPTH) fail("the answer nests more than " + MAX_DEPTH + " levels deep");
      return !failed;
    };
    function expression(depth) {
      if (!enter(depth)) return NaN;
      let v = term(depth);
      for (;;) {
        space();
        const c = peek();
        if (failed || (c !== "+" && c !== "-")) return v;
        pos++;
        const w = term(depth);
        v = c === "+" ? v + w : v - w;
      }
    }
    function term(depth) {
      let v = unary(depth);
      for (;;) {
        space();
        const c = peek();
        if (failed) return v;
        if (c === "*" && chars[pos + 1] === "*") return v;
        if (c === "*" || c === "/") {
          pos++;
          const w = unary(depth);
          v = c === "*" ? v * w : v / w;
        } else if (startsPrimary(c)) {
          v = v * unary(depth);
        } else {
          return v;
        }
      }
    }
    function unary(depth) {
      if (!enter(depth + 1)) return NaN;
      space();
      const c = peek();
      if (c === "-" || c === "+") {
        pos++;
        const v = unary(depth + 1);
        return c === "-" ? -v : v;
      }
      return power(depth + 1);
    }
    function power(depth) {
      let v = postfix(depth);
      space();
      if (failed) return v;
      const caret = peek() === "^", stars = peek() === "*" && chars[pos + 1] === "*";
      if (caret || stars) {
        pos += caret ? 1 : 2;
        v = Math.pow(v, unary(depth + 1));
      }
      return v;
    }
    // "30deg", "30 deg" or "30°": degrees, as radians.
    function degrees() {
      let at = pos;
      while (chars[at] === " " || chars[at] === "\t") at++;
      let width = 0;
      if (chars[at] === "\u00b0") width = 1;
      else if (chars.slice(at, at + 3).join("") === "deg" && !/^[A-Za-z0-9_]$/.test(chars[at + 3] || "")) width = 3;
      if (!width) return false;
      pos = at + width;
      return true;
    }
    function postfix(depth) {
      let v = primary(depth);
      for (;;) {
        if (!failed && degrees()) { v = v * Math.PI / 180; continue; }
        const c = peek();
        if (failed || (c !== "\u00b2" && c !== "\u00b3")) return v;
        pos++;
        v = Math.pow(v, c === "\u00b2" ? 2 : 3);
      }
    }
    function primary(depth) {
      if (!enter(depth + 1)) return NaN;
      space();
      const c = peek();
      if (c === "") return fail("the answer ends too early");
      if (c === "(") {
        pos++;
        const v = expression(depth + 1);
        space();
        if (failed) return v;
        if (peek() !== ")") return fail(pos >= chars.length ? "missing ')'" : "expected ')' but found '" + peek() + "'");
        pos++;
        return v;
      }
      if (c === "\u221a") { pos++; return Math.sqrt(postfix(depth + 1)); }
      if (c === "\u03c0") { pos++; return Math.PI; }
      if (isDigit(c) || c === ".") return number();
      if (isAlpha(c)) {
        const start = pos;
        while (pos < chars.length && /^[A-Za-z0-9_]$/.test(chars[pos])) pos++;
        return identifier(chars.slice(start, pos).join(""), start, depth);
      }
      return fail("unexpected '" + c + "'");
    }
    function number() {
      const start = pos;
      while (isDigit(peek())) pos++;
      if (peek() === ".") { pos++; while (isDigit(peek())) pos++; }
      if (peek() === "e" || peek() === "E") {
        let e = pos + 1;
        if (chars[e] === "+" || chars[e] === "-") e++;
        if (isDigit(chars[e] || "")) { pos = e; while (isDigit(peek())) pos++; }
      }
      const literal = chars.slice(start, pos).join("");
      if (literal === "." || literal === "") { pos = start; return fail("'" + literal + "' is not a number"); }
      if (peek() === ".") return fail("a second decimal point");
      return parseFloat(literal);
    }
    function identifier(name, start, depth) {
      space();
      if (FUNCS[name]) {
        if (peek() !== "(") return fail("expected '(' after " + name);
        if (name === "atan2") {
          pos++;
          const y = expression(depth + 1);
          space();
          if (failed) return NaN;
          if (peek() !== ",") return fail("expected ',' between the two arguments, found '" + (peek() || "end") + "'");
          pos++;
          const x = expression(depth + 1);
          space();
          if (failed) return NaN;
          if (peek() !== ")") return fail(pos >= chars.length ? "missing ')'" : "expected ')' but found '" + peek() + "'");
          pos++;
          return Math.atan2(y, x);
        }
        const x = primary(depth + 1);
        const f = {sqrt: Math.sqrt, abs: Math.abs, sin: Math.sin, cos: Math.cos, tan: Math.tan,
                   exp: Math.exp, ln: Math.log, log: Math.log, asin: Math.asin, acos: Math.acos,
                   atan: Math.atan}[name];
        return f ? f(x) : x;
      }
      if (name === "pi") return Math.PI;
      if (known[name]) return 1;
      pos = start;
      return fail(symbols ? "unknown symbol '" + name + "' (known: " + symbols.join(", ") + ")"
                          : "unknown name '" + name + "' (a number is expected)");
    }
    if (chars.length > MAX_LENGTH) return {ok: false, message: "the answer is too long (more than " + MAX_LENGTH + " characters)"};
    space();
    if (pos === chars.length) return {ok: false, message: "the answer is empty"};
    const value = expression(0);
    space();
    if (!failed && pos < chars.length) fail("unexpected '" + chars[pos] + "'");
    if (failed) return {ok: false, message: failed.message + " at character " + failed.column};
    return {ok: true, value: value};
  }

  // --- Inputs
  const inputs = [];  // every text input, with how to check it
  function el(tag, attrs, children) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attrs || {})) {
      if (k === "text") e.textContent = v; else e.setAttribute(k, v);
    }
    for (const c of children || []) e.appendChild(c);
    return e;
  }
  function check(input) {
    const hint = input.hint;
    const text = input.value;
    if (text.trim() === "") { hint.textContent = ""; input.classList.remove("bad"); return; }
    const r = readFormula(text, input.symbols);
    if (r.ok) {
      input.classList.remove("bad");
      hint.textContent = input.symbols ? "\u2713 reads as a formula" :
        (isFinite(r.value) ? "\u2713 reads as " + Number(r.value.toPrecision(6)) : "no finite value");
      hint.className = "hint " + (isFinite(r.value) || input.symbols ? "ok" : "err");
    } else {
      input.classList.add("bad");
      hint.textContent = "could not read this: " + r.message;
      hint.className = "hint err";
    }
  }
  function textInput(name, label, symbols) {
    const input = el("input", {type: "text", name: name, "aria-label": label, autocomplete: "off",
                               spellcheck: "false"});
    input.hint = el("span", {class: "hint", "aria-live": "polite"});
    input.symbols = symbols || null;
    input.addEventListener("input", () => { check(input); save(); });
    inputs.push(input);
    return input;
  }
  function numberBox(name, label) {
    const input = textInput(name, label);
    return {node: el("span", {class: "cell"}, [input, input.hint]),
            value: () => (input.value.trim() === "" ? undefined : input.value.trim())};
  }
  function vectorBox(name, label) {
    const parts = ["x", "y", "z"].map((a) => textInput(name + "." + a, label + " " + a));
    const node = el("span", {class: "vector"}, [el("span", {text: "("})]);
    parts.forEach((p, i) => {
      node.appendChild(p);
      if (i < 2) node.appendChild(el("span", {text: ","}));
    });
    node.appendChild(el("span", {text: ")"}));
    const hints = el("span", {class: "hints"}, parts.map((p) => p.hint));
    return {node: el("span", {class: "cell"}, [node, hints]),
            value: () => {
              const v = parts.map((p) => p.value.trim());
              return v.every((x) => x === "") ? undefined : v;
            }};
  }
  function yesNo(name, label) {
    const select = el("select", {name: name, "aria-label": label}, [
      el("option", {value: "", text: "\u2014"}), el("option", {value: "true", text: "yes"}),
      el("option", {value: "false", text: "no"})]);
    select.addEventListener("change", save);
    inputs.push(select);
    return {node: select, value: () => (select.value === "" ? undefined : select.value === "true")};
  }
  function box(type, name, label, symbols) {
    if (type === "vector") return vectorBox(name, label);
    if (type === "yesno") return yesNo(name, label);
    if (type === "formula") {
      const input = textInput(name, label, symbols);
      return {node: el("span", {class: "cell"}, [input, input.hint]),
              value: () => (input.value.trim() === "" ? undefined : input.value.trim())};
    }
    return numberBox(name, label);
  }
  function labelled(text, node) {
    return el("div", {class: "field"}, [el("span", {class: "label", text: text}), node]);
  }

  // A field: its node and a function giving its value (undefined when left blank).
  function hitsField(prefix, f) {
    const rows = [];
    const table = el("div", {class: "rows"});
    const miss = f.miss ? el("input", {type: "checkbox", name: prefix + ".miss"}) : null;
    const contained = f.contained ? el("input", {type: "checkbox", name: prefix + ".contained"}) : null;
    function addRow() {
      const n = rows.length;
      const cells = f.columns.map((c) => ({key: c.key, box: box(c.type, prefix + "." + n + "." + c.key, c.label + " of hit " + (n + 1))}));
      const row = el("div", {class: "row"}, cells.map((c) => labelled(c.key === "t" ? "t" : c.key, c.box.node)));
      rows.push(cells);
      table.appendChild(row);
      return row;
    }
    addRow();
    const node = el("div", {class: "hits"}, [table]);
    if (f.several) {
      const add = el("button", {type: "button", class: "add", text: "Add a hit"});
      add.addEventListener("click", () => { addRow(); save(); });
      const remove = el("button", {type: "button", class: "remove", text: "Remove the last hit"});
      remove.addEventListener("click", () => {
        if (rows.length > 1) { rows.pop(); table.removeChild(table.lastChild); save(); }
      });
      node.appendChild(el("div", {class: "buttons"}, [add, remove]));
    }
    for (const [box_, text] of [[miss, f.miss], [contained, f.contained]]) {
      if (!box_) continue;
      box_.addEventListener("change", save);
      inputs.push(box_);
      node.appendChild(el("label", {class: "flag"}, [box_, el("span", {text: " " + text})]));
    }
    return {node: node, rows: rows, addRow: addRow, apply: (answer) => {
      if (contained && contained.checked) { answer.hits = []; answer.contained = true; return; }
      if (miss && miss.checked) { answer.hits = []; return; }
      const hits = [];
      for (const cells of rows) {
        const hit = {};
        for (const c of cells) { const v = c.box.value(); if (v !== undefined) hit[c.key] = v; }
        if (Object.keys(hit).length) hits.push(hit);
      }
      if (hits.length) answer.hits = hits;
    }};
  }
  function rowsField(prefix, f) {
    const list = [];
    const node = el("div", {class: "rows"});
    f.rows.forEach((r, i) => {
      const cells = f.columns.map((c) => ({key: c.key, box: box(c.type, prefix + "." + i + "." + c.key, c.label + " for " + r.label)}));
      list.push({fixed: r.fixed, cells: cells});
      node.appendChild(el("div", {class: "row"}, [el("span", {class: "label", text: r.label})].concat(
        cells.map((c) => labelled(c.key.replace(/_/g, " "), c.box.node)))));
    });
    return {node: node, value: () => {
      const out = [];
      let any = false;
      for (const r of list) {
        const row = Object.assign({}, r.fixed);
        for (const c of r.cells) { const v = c.box.value(); if (v !== undefined) { row[c.key] = v; any = true; } }
        out.push(row);
      }
      return any ? out : undefined;
    }};
  }
  function choiceField(prefix, f) {
    const select = el("select", {name: prefix, "aria-label": f.label},
      [el("option", {value: "", text: "\u2014"})].concat(f.options.map((o, i) => el("option", {value: String(i), text: o.text}))));
    select.addEventListener("change", save);
    inputs.push(select);
    return {node: select, value: () => (select.value === "" ? undefined : f.options[Number(select.value)].value)};
  }
  function setField(prefix, f) {
    const boxes = f.options.map((o) => el("input", {type: "checkbox", name: prefix + "." + o}));
    boxes.forEach((b) => { b.addEventListener("change", save); inputs.push(b); });
    return {node: el("span", {}, boxes.map((b, i) => el("label", {class: "flag"}, [b, el("span", {text: " " + f.options[i] + " "})]))),
            value: () => { const v = f.options.filter((o, i) => boxes[i].checked); return v.length ? v : undefined; }};
  }
  function jsonField(prefix, f) {
    const area = el("textarea", {name: prefix, rows: "8", "aria-label": f.label, spellcheck: "false"});
    const hint = el("span", {class: "hint"});
    area.addEventListener("input", () => {
      try { if (area.value.trim()) JSON.parse(area.value); hint.textContent = area.value.trim() ? "\u2713 JSON" : ""; hint.className = "hint ok"; }
      catch (e) { hint.textContent = "not JSON yet: " + e.message; hint.className = "hint err"; }
      save();
    });
    inputs.push(area);
    return {node: el("div", {}, [area, hint]), value: () => {
      if (!area.value.trim()) return undefined;
      try { return JSON.parse(area.value); } catch (e) { return undefined; }
    }};
  }

  function setAt(answer, key, value) {
    if (key === "") { Object.assign(answer, value); return; }
    const parts = key.split("/");
    let at = answer;
    for (const p of parts.slice(0, -1)) at = at[p] = at[p] || {};
    at[parts[parts.length - 1]] = value;
  }

  const problems = [];
  for (const p of data.problems) {
    const form = document.getElementById("form-" + p.index);
    const fields = [];
    p.form.fields.forEach((f, i) => {
      const prefix = p.id + "." + i;
      let made;
      if (f.type === "hits") made = hitsField(prefix, f);
      else if (f.type === "rows") made = rowsField(prefix, f);
      else if (f.type === "choice") made = choiceField(prefix, f);
      else if (f.type === "set") made = setField(prefix, f);
      else if (f.type === "json") made = jsonField(prefix, f);
      else made = box(f.type, prefix, f.label, f.symbols);
      form.appendChild(f.type === "hits" ? el("div", {class: "field"}, [el("div", {class: "label", text: f.label}), made.node])
                                         : labelled(f.label, made.node));
      fields.push({f: f, made: made});
    });
    problems.push({id: p.id, fields: fields});
  }

  function answers() {
    const out = {};
    for (const p of problems) {
      const answer = {};
      for (const {f, made} of p.fields) {
        if (made.apply) { made.apply(answer); continue; }
        const v = made.value();
        if (v !== undefined) setAt(answer, f.key, v);
      }
      if (Object.keys(answer).length) out[p.id] = answer;
    }
    return out;
  }
  function submission() {
    const s = {student: data.student.identity, answers: answers()};
    if (!data.student.identity) delete s.student;
    return s;
  }

  // --- Progress, kept in this browser only
  function rowCounts() {
    const counts = {};
    for (const p of problems) for (const {f, made} of p.fields) if (made.rows) counts[p.id + "." + f.key] = made.rows.length;
    return counts;
  }
  function save() {
    const values = {};
    for (const i of inputs) values[i.name] = i.type === "checkbox" ? i.checked : i.value;
    try { localStorage.setItem(storageKey, JSON.stringify({values: values, rows: rowCounts()})); } catch (e) { /* storage off */ }
    document.getElementById("saved").textContent = "Saved in this browser.";
  }
  function restore() {
    let state = null;
    try { state = JSON.parse(localStorage.getItem(storageKey) || "null"); } catch (e) { state = null; }
    if (!state) return;
    for (const p of problems) for (const {f, made} of p.fields) {
      const n = state.rows && state.rows[p.id + "." + f.key];
      while (made.rows && n && made.rows.length < n) made.addRow();
    }
    for (const i of inputs) {
      if (!(i.name in state.values)) continue;
      if (i.type === "checkbox") i.checked = !!state.values[i.name]; else i.value = state.values[i.name];
      if (i.hint) check(i);
    }
  }

  document.getElementById("download").addEventListener("click", () => {
    const text = JSON.stringify(submission(), null, 2) + "\n";
    const a = document.createElement("a");
    a.href = URL.createObjectURL(new Blob([text], {type: "application/json"}));
    a.download = "answers.json";
    document.body.appendChild(a);
    a.click();
    setTimeout(() => { URL.revokeObjectURL(a.href); a.remove(); }, 1000);
  });
  document.getElementById("clear").addEventListener("click", () => {
    if (!confirm("Clear every answer on this page?")) return;
    try { localStorage.removeItem(storageKey); localStorage.removeItem(storageKey + ":practice"); } catch (e) { /* storage off */ }
    location.reload();
  });

  // --- Practice (raygrade handout --practice): graded in this page by raygrade.js, with the
  // assignment's feedback policy; attempts and results kept in this browser (docs/web.md).
  function practice() {
    const setup = data.practice;
    const progressKey = storageKey + ":practice";
    let progress = {};
    try { progress = JSON.parse(localStorage.getItem(progressKey) || "{}") || {}; } catch (e) { progress = {}; }
    const keep = () => { try { localStorage.setItem(progressKey, JSON.stringify(progress)); } catch (e) { /* storage off */ } };
    const views = {};
    let grader = null;
    const timing = {};
    window.raygradePractice = {timing: timing, ready: false};

    function showSolution(id, view) {
      if (view.solution.querySelector("iframe") || !grader) return;
      view.solution.textContent = "";
      const html = grader.solveAssignment(setup.files, setup.assignment, data.student.key, "html", id);
      const frame = el("iframe", {class: "solution", title: "Worked solution", sandbox: ""});
      frame.srcdoc = html;
      view.solution.appendChild(el("h3", {text: "Worked solution"}));
      view.solution.appendChild(frame);
    }
    // Points as people read them: 2, 1.5, 0.33.
    const pts = (x) => String(Number(Number(x).toFixed(2)));
    function render(id, result) {
      const view = views[id];
      const p = progress[id];
      view.attempts.textContent = "Attempts: " + p.attempts + (p.full ? " \u2014 full marks" : "");
      view.feedback.textContent = "";
      if (!result) return;
      const full = result.score >= result.max_score;
      view.feedback.className = "practice-feedback " + (full ? "right" : "wrong");
      view.feedback.appendChild(el("p", {class: "score", text: "Score: " + pts(result.score) + " / " + pts(result.max_score)}));
      const list = el("ul", {class: "parts"});
      for (const part of result.parts || []) {
        // A part worth no points was not asked: checked, shown without a verdict or a score.
        const counted = !(part.max_points === 0);
        const item = el("li", {class: "part " + (counted ? part.status : "not-counted"), "data-part": part.name});
        const points = counted && part.points !== undefined ? " (" + pts(part.points) + " / " + pts(part.max_points) + ")" : "";
        item.appendChild(el("strong", {text: part.name + ": " + (counted ? part.status : "not counted") + points}));
        for (const line of part.feedback || []) item.appendChild(el("div", {text: line}));
        list.appendChild(item);
      }
      view.feedback.appendChild(list);
      for (const m of result.mistakes || []) {
        view.feedback.appendChild(el("p", {class: "mistake", "data-mistake": m.id, text: m.message}));
      }
      for (const n of result.notes || []) view.feedback.appendChild(el("p", {class: "note", text: n}));
      if (p.full || p.attempts >= setup.unlock_after) showSolution(id, view);
      else view.solution.textContent = "The worked solution opens with full marks or after " + setup.unlock_after + " attempts.";
    }
    function checkProblem(id) {
      const answer = answers()[id];
      const submission = {answers: {}};
      if (data.student.identity) submission.student = data.student.identity;
      if (answer) submission.answers[id] = answer;
      const start = performance.now();
      // The files never change while the page is open: the assignment is read once.
      const out = grader.gradeAssignment(setup.files, setup.assignment, JSON.stringify(submission),
                                         {cacheKey: "page"});
      timing.lastCheckMs = performance.now() - start;
      let graded = null;
      try { graded = JSON.parse(out).submissions[0]; } catch (e) { graded = null; }
      const view = views[id];
      if (!graded || !graded.gradable) {
        view.feedback.className = "practice-feedback wrong";
        view.feedback.textContent = "Could not grade: " + (graded && graded.fault ? graded.fault.message : grader.lastErrors().join("; "));
        return;
      }
      const result = graded.problems.find((r) => r.problem === id);
      const p = progress[id] = progress[id] || {attempts: 0, full: false};
      p.attempts += 1;
      p.full = p.full || (result && result.answered && result.score >= result.max_score);
      p.last = result;
      keep();
      render(id, result);
    }
    for (const p of data.problems) {
      const section = document.getElementById("problem-" + p.index);
      const button = el("button", {type: "button", class: "check", "data-problem": p.id, text: "Check", disabled: ""});
      const view = {button: button, attempts: el("span", {class: "attempts muted"}),
                    feedback: el("div", {class: "practice-feedback"}), solution: el("div", {class: "solution-box"})};
      views[p.id] = view;
      button.addEventListener("click", () => checkProblem(p.id));
      section.appendChild(el("div", {class: "practice"}, [button, view.attempts, view.feedback, view.solution]));
    }
    const status = el("span", {id: "grader-status", class: "muted", text: "Loading the grader\u2026"});
    document.getElementById("actions").appendChild(status);
    const start = performance.now();
    createRaygrade().then((g) => {
      grader = g;
      timing.readyMs = performance.now() - start;
      status.textContent = "The grader runs in this page; nothing is sent anywhere.";
      for (const id of Object.keys(views)) {
        views[id].button.removeAttribute("disabled");
        if (progress[id]) render(id, progress[id].last);
      }
      window.raygradePractice.ready = true;
      // Read the assignment and draw this student's variants once, right away, so that the
      // first Check costs the grading alone (and the module's code is compiled by then).
      setTimeout(() => {
        const warm = performance.now();
        const empty = data.student.identity ? {student: data.student.identity, answers: {}} : {answers: {}};
        grader.gradeAssignment(setup.files, setup.assignment, JSON.stringify(empty), {cacheKey: "page"});
        timing.warmUpMs = performance.now() - warm;
      }, 0);
    }, (e) => { status.textContent = "The grader could not start: " + e; });
  }
  if (data.practice) practice();
  restore();
  window.raygradeHandout = {readFormula: readFormula, submission: submission};
})();
