// The handout page: answer inputs built from each problem's form, typed numbers read as the
// grader reads them, progress kept in the browser, and answers.json downloaded in the
// submission format. Nothing is sent anywhere, but to the LMS of a SCORM package
// (scorm_page.js).
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("handout-data").textContent);
  // The LMS around a SCORM package's page, or null. One package serves a whole class, so in
  // an LMS the browser's copy is the learner's own: two students on one computer do not see
  // each other's answers.
  const lms = window.raygradeLms || null;
  const storageKey = "raygrade:" + data.assignment.id + ":" + (data.student.key || "") +
    (lms ? ":lms:" + lms.learner : "");

  // --- Typed numbers and formulas, read by the grader's own reader: its C++ (formula parser and
  // answer reader) compiled alone to WebAssembly, typed_reader.js, put here when the build is
  // configured (scripts/build-typed-reader.sh; docs/web.md). The page cannot read a box
  // otherwise than the grader does.
  /* @RAYGRADE_TYPED_READER@ */
  const typedReader = createTypedReader();
  const fromBits = (hex) => {
    const b = new DataView(new ArrayBuffer(8));
    b.setBigUint64(0, BigInt("0x" + hex));
    return b.getFloat64(0);
  };
  // The grader's reading of a box's value (a string, or three for a vector) as a submission
  // carries it: {ok, values} or {ok: false, message, fault}.
  function readTyped(box, value, symbols) {
    const r = JSON.parse(typedReader.ccall("raygrade_read_typed", "string",
      ["string", "string", "string"], [box, JSON.stringify(value), (symbols || []).join(",")]));
    if (r.ok) r.values = r.values.map(fromBits);
    return r;
  }
  // What a box saves in answers.json: the text as typed, nothing when it is blank.
  function typedValue(text) { return text.trim() === "" ? undefined : text; }
  // The field types (kinds/fields/ of the grader, data.field_types): each one's shape and the
  // value a student gives, by which the page builds its inputs. The page never tests a type's
  // name: a type it does not know is shown as such, never taken for another.
  const fieldTypes = data.field_types;
  function fieldType(f) {
    return Object.prototype.hasOwnProperty.call(fieldTypes, f.type) ? fieldTypes[f.type] : null;
  }
  // The name of the field type of one typed value: the typed reader reads a box by its type.
  function typedBoxOf(value) {
    return Object.keys(fieldTypes).find((n) => fieldTypes[n].shape === "one" && fieldTypes[n].value === value);
  }
  // A box's check: blank (nothing shown, nothing saved), or the grader's verdict on its text.
  function boxReading(text, symbols) {
    if (typedValue(text) === undefined) return {blank: true};
    const r = readTyped(typedBoxOf(symbols ? "typed-formula" : "typed-number"), text, symbols);
    return r.ok ? {ok: true, value: r.values[0]} : {ok: false, message: r.message, fault: r.fault};
  }
  function readFormula(text, symbols) {
    const r = readTyped(typedBoxOf("typed-formula"), text, symbols || []);
    return r.ok ? {ok: true, value: r.values[0]} : {ok: false, message: r.message};
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
    const r = boxReading(input.value, input.symbols);
    if (r.blank) { hint.textContent = ""; input.classList.remove("bad"); return; }
    if (r.ok || r.fault === "finite") {
      input.classList.remove("bad");
      hint.textContent = !r.ok ? "no finite value" : input.symbols ? "\u2713 reads as a formula" :
        "\u2713 reads as " + Number(r.value.toPrecision(6));
      hint.className = "hint " + (r.ok ? "ok" : "err");
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
            value: () => typedValue(input.value)};
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
              const v = parts.map((p) => typedValue(p.value));
              return v.every((x) => x === undefined) ? undefined : v.map((x) => x || "");
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
  // A field of a type the page does not know: said so where its input would be, and nothing
  // saved for it.
  function unknownField(f) {
    return {node: el("span", {class: "hint err", role: "alert",
                              text: "This page cannot show an answer box of type \u201c" + String(f.type) +
                                    "\u201d: tell your instructor."}),
            value: () => undefined};
  }
  // One box of a field or of a table's column, by the value it takes.
  function box(f, name, label) {
    const t = fieldType(f);
    const value = t && t.shape === "one" ? t.value : null;
    if (value === "typed-three") return vectorBox(name, label);
    if (value === "flag") return yesNo(name, label);
    if (value === "typed-formula") {
      const input = textInput(name, label, f.symbols);
      return {node: el("span", {class: "cell"}, [input, input.hint]),
              value: () => typedValue(input.value)};
    }
    if (value === "typed-number") return numberBox(name, label);
    return unknownField(f);
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
      const cells = f.columns.map((c) => ({key: c.key, box: box(c, prefix + "." + n + "." + c.key, c.label + " of hit " + (n + 1))}));
      const row = el("div", {class: "row"}, cells.map((c) => labelled(c.key, c.box.node)));
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
      const cells = f.columns.map((c) => ({key: c.key, box: box(c, prefix + "." + i + "." + c.key, c.label + " for " + r.label)}));
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
  // A ray tree, point by point: where each point's ray comes from, what it meets, its shadow
  // ray toward each light, and the Phong terms that apply there; shown as a tree while it is
  // being built. Points are named I1, I2, ... in the order of the list.
  const TERM_SETS = [["ambient"], ["ambient", "diffuse"], ["ambient", "specular"], ["ambient", "diffuse", "specular"]];
  const TERM_TEXT = ["ambient only", "ambient and diffuse", "ambient and specular", "ambient, diffuse and specular"];
  const SHADOW_TEXT = {lit: "reaches the light (lit)", shadow: "is blocked (in shadow)", away: "the surface faces away"};
  const NOTHING = "\u0000nothing";
  function treeField(prefix, f) {
    const asks = f.asks || [];
    const askShadows = asks.indexOf(f.shadows_part) >= 0 && f.lights.length > 0;
    const askTerms = asks.indexOf(f.terms_part) >= 0;
    const points = [];
    let nextId = 1;
    const list = el("ol", {class: "tree-points"});
    const outline = el("div", {class: "tree-outline"});
    const name = (pt) => "I" + (points.indexOf(pt) + 1);
    const byId = (id) => points.find((q) => q.id === id);
    function select(label, options, className) {
      const s = el("select", {"aria-label": label, class: className || ""},
        [el("option", {value: "", text: "\u2014"})].concat(options.map(([v, t]) => el("option", {value: v, text: t}))));
      s.addEventListener("change", () => { refresh(); save(); });
      return s;
    }
    // "the eye", or a reflection or refraction at another point: kept by the point's id, so
    // that moving or removing points renames, never rewires.
    function fillFrom(pt) {
      const keep = pt.from.value;
      pt.from.textContent = "";
      const options = [["", "\u2014"], ["eye", "the eye (the primary ray)"]];
      for (const q of points) {
        if (q === pt) continue;
        options.push(["R:" + q.id, "the reflection at " + name(q)], ["T:" + q.id, "the refraction at " + name(q)]);
      }
      for (const [v, t] of options) pt.from.appendChild(el("option", {value: v, text: t}));
      pt.from.value = options.some(([v]) => v === keep) ? keep : "";
    }
    function relabel() {
      points.forEach((pt) => {
        const n = name(pt);
        pt.title.textContent = "Point " + n;
        pt.from.setAttribute("aria-label", n + ": the ray that meets it");
        pt.object.setAttribute("aria-label", n + ": the object it is on");
        pt.lights.forEach((l, i) => {
          l.status.setAttribute("aria-label", "The shadow ray of " + n + " toward " + f.lights[i]);
          l.boxes.forEach((b, j) => b.setAttribute("aria-label", "The shadow ray of " + n + " toward " + f.lights[i] + " is blocked by " + f.objects[j]));
        });
        if (pt.terms) pt.terms.setAttribute("aria-label", n + ": the Phong terms that apply");
        fillFrom(pt);
      });
    }
    function refresh() {
      for (const pt of points) for (const l of pt.lights) l.blockers.hidden = l.status.value !== "shadow";
      drawOutline();
    }
    function describe(pt) {
      const v = pt.object.value;
      let text = name(pt) + ": " + (v === NOTHING ? "leaves the scene" : v ? "on " + v : "object not chosen");
      const said = pt.lights.map((l, i) => l.status.value ? "toward " + f.lights[i] + " " + SHADOW_TEXT[l.status.value] : "").filter((x) => x);
      if (said.length) text += "; shadow ray " + said.join(", ");
      if (pt.terms && pt.terms.value !== "") text += "; " + TERM_TEXT[Number(pt.terms.value)];
      return text;
    }
    function drawOutline() {
      outline.textContent = "";
      outline.appendChild(el("p", {class: "label", text: "The tree so far"}));
      const seen = new Set();
      function branch(parentId) {
        const ul = el("ul", {});
        for (const pt of points) {
          const from = pt.from.value;
          const mine = parentId === null ? from === "eye" : from.slice(2) === String(parentId);
          if (!mine || seen.has(pt)) continue;
          seen.add(pt);
          const how = parentId === null ? "primary ray" : (from[0] === "R" ? "reflection" : "refraction");
          const li = el("li", {text: how + " \u2192 " + describe(pt)});
          const sub = branch(pt.id);
          if (sub.childNodes.length) li.appendChild(sub);
          ul.appendChild(li);
        }
        return ul;
      }
      const tree = branch(null);
      outline.appendChild(tree.childNodes.length ? tree : el("p", {class: "muted", text: "No point comes from the eye yet."}));
      const loose = points.filter((pt) => !seen.has(pt));
      if (loose.length) outline.appendChild(el("p", {class: "muted", text: "Not attached yet: " + loose.map(name).join(", ") + "."}));
    }
    function addPoint(state) {
      const pt = {id: state && state.id ? state.id : nextId};
      nextId = Math.max(nextId, pt.id) + 1;
      pt.title = el("strong", {});
      pt.from = el("select", {class: "tree-from"});
      pt.from.addEventListener("change", () => { refresh(); save(); });
      pt.object = select("object", f.objects.map((o) => [o, o]).concat([[NOTHING, "nothing: the ray leaves the scene"]]), "tree-object");
      pt.lights = [];
      const cells = [labelled("comes from", pt.from), labelled("meets", pt.object)];
      if (askShadows) {
        f.lights.forEach((light, i) => {
          const status = select("shadow ray", Object.keys(SHADOW_TEXT).map((k) => [k, SHADOW_TEXT[k]]), "tree-light");
          const boxes = f.objects.map((o) => {
            const b = el("input", {type: "checkbox", class: "tree-blocker", value: o});
            b.addEventListener("change", () => { refresh(); save(); });
            return b;
          });
          const blockers = el("span", {class: "tree-blockers"}, [el("span", {text: " blocked by: "})].concat(
            boxes.map((b, j) => el("label", {class: "flag"}, [b, el("span", {text: " " + f.objects[j] + " "})]))));
          pt.lights.push({status: status, boxes: boxes, blockers: blockers});
          cells.push(el("div", {class: "field"}, [el("span", {class: "label", text: "shadow ray toward " + light}), status, blockers]));
        });
      }
      if (askTerms) {
        pt.terms = select("terms", TERM_TEXT.map((t, i) => [String(i), t]), "tree-terms");
        cells.push(labelled("Phong terms", pt.terms));
      }
      const up = el("button", {type: "button", class: "tree-up", text: "Move up"});
      const down = el("button", {type: "button", class: "tree-down", text: "Move down"});
      const remove = el("button", {type: "button", class: "tree-remove", text: "Remove"});
      const move = (by) => {
        const i = points.indexOf(pt), j = i + by;
        if (j < 0 || j >= points.length) return;
        points.splice(i, 1);
        points.splice(j, 0, pt);
        list.insertBefore(pt.node, by < 0 ? points[j + 1].node : points[j - 1].node.nextSibling);
        relabel(); refresh(); save();
      };
      up.addEventListener("click", () => move(-1));
      down.addEventListener("click", () => move(1));
      remove.addEventListener("click", () => {
        points.splice(points.indexOf(pt), 1);
        list.removeChild(pt.node);
        relabel(); refresh(); save();
      });
      pt.node = el("li", {class: "tree-point"}, [el("div", {}, [pt.title]), el("div", {class: "row"}, cells),
                                                 el("div", {class: "buttons"}, [up, down, remove])]);
      points.push(pt);
      list.appendChild(pt.node);
      relabel();
      if (state) put(pt, state);
      refresh();
      return pt;
    }
    // A point's choices from its saved state.
    function put(pt, state) {
      pt.from.value = state.from || "";
      pt.object.value = state.object || "";
      (state.lights || []).forEach((l, i) => {
        if (!pt.lights[i]) return;
        pt.lights[i].status.value = l.status || "";
        pt.lights[i].boxes.forEach((b) => { b.checked = (l.blockers || []).indexOf(b.value) >= 0; });
      });
      if (pt.terms) pt.terms.value = state.terms || "";
    }
    const add = el("button", {type: "button", class: "tree-add", text: "Add a point"});
    add.addEventListener("click", () => { addPoint(null); save(); });
    const node = el("div", {class: "tree"}, [list, el("div", {class: "buttons"}, [add]), outline]);
    drawOutline();
    return {node: node, addPoint: addPoint,
      state: () => points.map((pt) => ({id: pt.id, from: pt.from.value, object: pt.object.value,
        lights: pt.lights.map((l) => ({status: l.status.value, blockers: l.boxes.filter((b) => b.checked).map((b) => b.value)})),
        terms: pt.terms ? pt.terms.value : ""})),
      load: (states) => {
        // Ids first, so that every "comes from" can name any point.
        for (const st of states) addPoint({id: st.id});
        relabel();
        states.forEach((st, k) => put(points[k], st));
        refresh();
      },
      apply: (answer) => {
        const nodes = [];
        for (const pt of points) {
          const from = pt.from.value;
          if (!from) continue;  // a point not attached to the tree is not sent
          const n = {label: name(pt)};
          if (from === "eye") { n.parent = null; n.ray = "primary"; }
          else {
            const parent = byId(Number(from.slice(2)));
            if (!parent) continue;
            n.parent = name(parent);
            n.ray = from[0] === "R" ? "reflection" : "refraction";
          }
          if (pt.object.value === NOTHING) n.object = null;
          else if (pt.object.value) n.object = pt.object.value;
          const statuses = pt.lights.map((l) => l.status.value);
          if (statuses.some((x) => x)) {
            const lit = statuses.indexOf("lit") >= 0, blocked = statuses.indexOf("shadow") >= 0;
            n.in_shadow = !lit && blocked;
            if (n.in_shadow) {
              const by = [];
              pt.lights.forEach((l) => { if (l.status.value === "shadow") for (const b of l.boxes) if (b.checked && by.indexOf(b.value) < 0) by.push(b.value); });
              if (by.length) n.shadowed_by = by;
            }
          }
          if (pt.terms && pt.terms.value !== "") n.terms = TERM_SETS[Number(pt.terms.value)].slice();
          nodes.push(n);
        }
        if (nodes.length) answer.nodes = nodes;
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
      const t = fieldType(f) || {};
      let made;
      if (t.shape === "open-table") made = hitsField(prefix, f);
      else if (t.shape === "fixed-rows") made = rowsField(prefix, f);
      else if (t.shape === "tree-builder") made = treeField(prefix, f);
      else if (t.value === "one-of") made = choiceField(prefix, f);
      else if (t.value === "some-of") made = setField(prefix, f);
      else made = box(f, prefix, f.label);
      form.appendChild(t.shape === "open-table" || t.shape === "tree-builder" ? el("div", {class: "field"}, [el("div", {class: "label", text: f.label}), made.node])
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
  let practiceProgress = null;  // practice(): the attempts and scores, for the LMS's copy
  function save() {
    const values = {};
    for (const i of inputs) values[i.name] = i.type === "checkbox" ? i.checked : i.value;
    const trees = {};
    for (const p of problems) p.fields.forEach(({made}, i) => { if (made.state) trees[p.id + "." + i] = made.state(); });
    const state = {values: values, rows: rowCounts(), trees: trees};
    try { localStorage.setItem(storageKey, JSON.stringify(state)); } catch (e) { /* storage off */ }
    document.getElementById("saved").textContent =
      lms ? lms.save(state, practiceProgress ? practiceProgress() : {}) : "Saved in this browser.";
  }
  function restore() {
    // The LMS's copy first: it follows the student to another computer.
    let state = lms && lms.resumed;
    if (!state) try { state = JSON.parse(localStorage.getItem(storageKey) || "null"); } catch (e) { state = null; }
    // A copy of another shape (an older page's, or damaged) is not read.
    if (!state || typeof state.values !== "object" || state.values === null) return;
    for (const p of problems) for (const {f, made} of p.fields) {
      const n = state.rows && state.rows[p.id + "." + f.key];
      while (made.rows && n && made.rows.length < n) made.addRow();
    }
    for (const p of problems) p.fields.forEach(({made}, i) => {
      const t = state.trees && state.trees[p.id + "." + i];
      if (made.load && Array.isArray(t)) made.load(t);
    });
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
    if (lms) lms.clear();
    try { localStorage.removeItem(storageKey); localStorage.removeItem(storageKey + ":practice"); } catch (e) { /* storage off */ }
    location.reload();
  });

  // --- Practice (raygrade handout --practice): graded in this page by raygrade.js, with the
  // assignment's feedback policy; attempts and results kept in this browser (docs/web.md).
  function practice() {
    const setup = data.practice;
    // Who the grader grades: the page's student; a generic page names nobody, which the grader
    // takes as the generic set when the numbers are everyone's.
    const student = data.student.identity || null;
    const progressKey = storageKey + ":practice";
    let progress = {};
    try { progress = JSON.parse(localStorage.getItem(progressKey) || "{}") || {}; } catch (e) { progress = {}; }
    if (lms && lms.resumed) progress = lms.resumed.progress || {};
    // Progress an older page kept (or a damaged copy): each field takes its default.
    if (typeof progress !== "object" || Array.isArray(progress)) progress = {};
    for (const [id, p] of Object.entries(progress)) {
      if (!p || typeof p !== "object") { delete progress[id]; continue; }
      if (!(Number.isInteger(p.attempts) && p.attempts >= 0)) p.attempts = 0;
      p.full = p.full === true;
      if (!Number.isFinite(p.score)) p.score = 0;
      if (!Number.isFinite(p.max)) p.max = 0;
    }
    practiceProgress = () => progress;
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
      // Progress resumed from an LMS carries no feedback, but still unlocks the solution.
      if (!result) {
        if (p.full || p.attempts >= setup.unlock_after) showSolution(id, view);
        return;
      }
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
      if (student) submission.student = student;
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
      p.score = result ? result.score : 0;
      p.max = result ? result.max_score : 0;
      keep();
      render(id, result);
      if (lms) report(graded.problems);
    }
    // The LMS gets the score on the whole assignment: each problem's last Check, 0 for a
    // problem not checked yet; passed when every problem's last Check earned all its points.
    function report(results) {
      let points = 0, maxPoints = 0, passed = results.length > 0;
      for (const r of results) {
        const p = progress[r.problem];
        maxPoints += r.max_score;
        points += p ? p.score || 0 : 0;
        if (!p || !(p.max > 0 ? p.score >= p.max : p.attempts > 0)) passed = false;
      }
      save();
      lms.report(points, maxPoints, passed);
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
      // From the start of the navigation to the page (performance's time origin) to Check.
      timing.readyAfterNavigationMs = performance.now();
      status.textContent = lms ? "The grader runs in this page; each Check sends your score to your course's site."
                               : "The grader runs in this page; nothing is sent anywhere.";
      for (const id of Object.keys(views)) {
        views[id].button.removeAttribute("disabled");
        if (progress[id]) render(id, progress[id].last);
      }
      window.raygradePractice.ready = true;
      // Read the assignment and draw this student's variants once, right away, so that the
      // first Check costs the grading alone (and the module's code is compiled by then).
      setTimeout(() => {
        const warm = performance.now();
        const empty = student ? {student: student, answers: {}} : {answers: {}};
        grader.gradeAssignment(setup.files, setup.assignment, JSON.stringify(empty), {cacheKey: "page"});
        timing.warmUpMs = performance.now() - warm;
      }, 0);
    }, (e) => { status.textContent = "The grader could not start: " + e; });
  }
  if (data.practice) practice();
  restore();
  window.raygradeHandout = {readFormula: readFormula, submission: submission};
})();

// Dates in the student's own time, with UTC beside them: a <time datetime> holds the UTC text
// ("Friday 4 December 2026, 23:59 UTC"), which is what a browser without script shows.
(function () {
  const DAYS = ["Sunday", "Monday", "Tuesday", "Wednesday", "Thursday", "Friday", "Saturday"];
  const MONTHS = ["January", "February", "March", "April", "May", "June", "July", "August",
                  "September", "October", "November", "December"];
  const two = (n) => String(n).padStart(2, "0");
  for (const time of document.querySelectorAll("time[datetime]")) {
    const d = new Date(time.getAttribute("datetime"));
    if (isNaN(d.getTime()) || d.getTimezoneOffset() === 0) continue;  // UTC is the local time
    const local = DAYS[d.getDay()] + " " + d.getDate() + " " + MONTHS[d.getMonth()] + " " + d.getFullYear();
    const utc = DAYS[d.getUTCDay()] + " " + d.getUTCDate() + " " + MONTHS[d.getUTCMonth()] + " " + d.getUTCFullYear();
    const utcTime = two(d.getUTCHours()) + ":" + two(d.getUTCMinutes()) + " UTC";
    time.textContent = local + ", " + two(d.getHours()) + ":" + two(d.getMinutes()) +
      " (your time; " + (local === utc ? utcTime : utc + ", " + utcTime) + ")";
  }
})();
