// The handout page's own input check on the typed corpus (tests/typed_corpus.py): the page's
// reader is taken from a generated page (the script between "// --- Typed numbers" and
// "// --- Inputs", with the page's own data), run in Node, and each box's verdict, value and
// the text the page would save are written as JSON.
// Usage: node typed_corpus_page.js PAGE.html CORPUS.json OUT.json
"use strict";
const fs = require("fs");
const vm = require("vm");

const [page, corpusFile, outFile] = process.argv.slice(2);
const html = fs.readFileSync(page, "utf8");
const dataMatch = html.match(/<script[^>]*id="handout-data"[^>]*>([\s\S]*?)<\/script>/);
const start = html.indexOf("// --- Typed numbers");
const end = html.indexOf("// --- Inputs", start);
if (!dataMatch || start < 0 || end < 0) {
  console.error("typed_corpus_page.js: the page's reader or data is not found in " + page);
  process.exit(2);
}
const data = JSON.parse(dataMatch[1]);
const context = vm.createContext({data: data, console: console});
vm.runInContext(html.slice(start, end) + "\nthis.reader = {readFormula: readFormula," +
                " boxReading: typeof boxReading === 'function' ? boxReading : null," +
                " typedValue: typeof typedValue === 'function' ? typedValue : null};", context);
const reader = context.reader;

// The page's check of one input (handout_page.js, check()): blank, or read with its verdict.
function checkOne(text, symbols) {
  if (reader.boxReading) return reader.boxReading(text, symbols);
  if (text.trim() === "") return {blank: true};
  const r = reader.readFormula(text, symbols);
  if (!r.ok) return {ok: false, message: r.message};
  if (!symbols && !isFinite(r.value)) return {ok: false, message: "no finite value"};
  return {ok: true, value: r.value};
}
// What the page writes into answers.json for a box (its value() functions).
const saved = (text) => (reader.typedValue ? reader.typedValue(text)
                                           : (text.trim() === "" ? undefined : text.trim()));
function bits(v) {
  const b = new DataView(new ArrayBuffer(8));
  b.setFloat64(0, v);
  return b.getBigUint64(0).toString(16).padStart(16, "0");
}

const out = [];
for (const item of JSON.parse(fs.readFileSync(corpusFile, "utf8"))) {
  const texts = item.box === "vector" ? item.text : [item.text];
  const symbols = item.box === "formula" ? item.symbols : null;
  const readings = texts.map((t) => checkOne(t, symbols));
  const ok = readings.every((r) => r.ok);
  const values = texts.map((t) => saved(t));
  out.push({
    ok: ok,
    values: ok ? readings.map((r) => bits(r.value)) : [],
    message: ok ? "" : (readings.find((r) => !r.ok).message || "blank"),
    saved: values.every((v) => v === undefined) ? null
           : (item.box === "vector" ? values.map((v) => (v === undefined ? "" : v)) : values[0]),
  });
}
fs.writeFileSync(outFile, JSON.stringify(out));
