#!/usr/bin/env python3
"""The differential test of typed answers: one corpus of typed inputs, in a number box, a vector
box (three numbers) and a formula box, read by every front end and by the grader, which must
agree on every one.

- The grader: `raygrade read-typed` reads each box's value as a submission carries it (JSON text),
  with AnswerReader and the formula parser: accepted or refused, and the value (its bits).
- The handout page: its own input check, taken from a page `raygrade handout` writes and run in
  Node (typed_corpus_page.js): the verdict it shows, the value, and the text it saves; the saved
  text, read by the grader, must mean what the typed text means.
- PrairieLearn: server.py's reading of an input (grader/assignments/platforms/prairielearn_server.py, its
  _text and _vector), then the grader on the text it hands on; a vector is typed into one box
  as "(x, y, z)".

The corpus is hand-picked edge cases (literals beyond a double, glyphs, degrees, controls, bidi
marks, lone surrogates, a byte-order mark, decimal commas, the length and nesting limits) and
inputs drawn by a small seeded grammar. A disagreement is a verdict (accepted or refused) that
differs, or a value that differs beyond its last bits (LAST_BITS; two NaNs of a formula agree).

Usage: typed_corpus.py RAYGRADE REPOSITORY WORK [--show N]
Prints the number of inputs and of disagreements by front end; exit status 1 on any.
"""
import importlib.util
import json
import os
import random
import subprocess
import sys

RAYGRADE, REPO, WORK = sys.argv[1:4]
SHOW = int(sys.argv[sys.argv.index("--show") + 1]) if "--show" in sys.argv else 12
SEED = 20261207
SYMBOLS = ["px", "py", "pz", "vx", "vy", "vz", "r"]

# --- The corpus

NUMBERS = [
    # literals at and beyond the doubles
    "1e-324", "-1e-324", "2.4e-324", "2.5e-324", "4.9e-324", "5e-324", "1e-320", "2.2250738585072014e-308",
    "1e309", "-1e309", "1.7976931348623157e308", "1.7976931348623158e308", "1.7976931348623159e308",
    "1e308*10", "0e999999", "1e-99999", "0.000", "1e400/1e300", "2^1024", "2^1023", "exp(709)",
    "exp(710)", "1/0", "0/0", "-0", "0", "-0.0", "+0", "ln(0)", "log(-1)", "sqrt(-1)", "√-1",
    # number syntax
    ".e5", ".5", "5.", "5.e3", ".5e1", "e5", "E5", "1e", "1e+", "1e-", "1e+5", "1E5", "1e05", "1e5.5",
    "1.2.3", "1..2", "..", ".", "..5", "0.1e-2", "00012", "0x10", "0b1", "1_000", "1'000", "1 000",
    "1 .5", "1. 5", "1e 5", "1 e5", "inf", "Infinity", "-inf", "nan", "NaN", "e", "E", "pi", "PI",
    "Pi", "2pi", "2 pi", "pi2", "1.5e3", "-1.5E-3", "7.27", "-0.50", "123456789012345678901234567890",
    "0.1", "0.30000000000000004", "3.141592653589793", "1e22", "1e23", "9007199254740993",
    # operators and glyphs
    "2*·3", "2·*3", "2··3", "2·3", "2⋅3", "2×3", "2÷3", "2−3", "−2", "2**3", "2^3", "2^-1", "2**-1",
    "2^^3", "2***3", "2*^3", "2^·3", "2²", "2³", "2²³", "2³²", "(2)²", "2^2²", "√2", "√(2)", "√√16",
    "2√2", "√2²", "π", "2π", "π2", "3π/4", "ππ", "−π", "√π", "2 × 3", "2 ÷ 0", "1/3", "1 / 3",
    "9 - sqrt(3)", "2(3)", "(2)(3)", "2 3", "2(3", "2)3", "-(-(-1))", "--1", "-+1", "+-1", "+1",
    "- 1", "++1", "1-", "1+", "*1", "/1", "^1", "²", "√", "1²²", "¹", "⁴", "½", "2½", "1⁄2",
    # degrees
    "30°", "30deg", "30 deg", "30  deg", "30\tdeg", "30degx", "30 degrees", "30°°", "30deg°",
    "sin(30deg)", "sin(30°)", "cos(60°)", "°30", "deg", "90°-30°", "sin 30°", "2*30°", "30° 2",
    "30 °", "30deg2", "tan(45 deg)", "1e1°", "π°",
    # functions
    "sqrt(2)", "sqrt 2", "sqrt2", "Sqrt(2)", "SQRT(2)", "sin(1)", "sin 1", "sin(1)²", "sin²(1)",
    "abs(-3)", "abs(-3", "exp(1)", "ln(2)", "log(2)", "log10(2)", "asin(2)", "acos(0.5)",
    "atan(1)", "atan2(1,2)", "atan2(1, 2)", "atan2(1;2)", "atan2(1)", "atan2(1,2,3)", "atan2(,)",
    "sin()", "sin", "foo(1)", "x", "_", "_1", "1_", "a1",
    # separators and commas
    "1,5", "0,25", "-0,5", "1,000", "1.000,5", "3,14e2", "1;2", "1:2", "1/2/3", "[1]", "{1}", "(1)",
    "((1))", "(1", "1)", "()", ")(", "(", ")",
    # spaces and invisible characters
    " 1", "1 ", "  1  ", "\t1\t", " ", "", "\t", "\u00a01", "1\u00a0", "\u20031", "1\u2003",
    "\u30001", "\u20091\u2009", "\u200b1", "1\u200b", "1\u200d", "\u2060" "1", "\ufeff1", "1\ufeff",
    "\ufeff", "\ufeff \ufeff", "1\u00ad",
    # controls
    "\x00", "1\x00", "\x001", "\x01", "\x012", "\x01 4", "2\x02", "2\x03", "\x04", "2\x04",
    "1\x7f", "1\n", "\n1", "1\r\n", "1\r", "1\x0b", "1\x0c", "\x1b[0m1", "1\x85", "1\x9b",
    "1\u2028", "1\u2029",
    # bidirectional marks
    "\u202e1", "1\u202e", "\u202d1\u202c", "1\u200f", "\u200e1", "\u2066 1\u2069", "\u061c1",
    "\u202b-1\u202c",
    # surrogates and characters beyond the BMP
    "\ud800", "1\ud800", "\udc00", "1\udc00", "\ud83d", "\ud800\ud800", "\udc00\ud800", "1😀",
    "😀", "𝟏", "1𝟏",
    # other scripts' digits and look-alikes
    "１", "１２", "٣", "۳", "३", "〇", "Ⅻ", "–1", "—1", "‒1", "﹣1", "－1", "1＋1", "1*1", "1∗1",
    "1∙1", "1•1", "1x1", "1X1", "2∕3", "2⁄3", "√２", "∞", "-∞", "ε", "µ", "Ω",
    # markup
    "<b>1</b>", "&amp;", "1&lt;2", "\\frac{1}{2}", "$1$", "\"1\"", "'1'", "`1`",
]
# The limits: length in bytes of UTF-8 and nesting depth.
LONG = [
    "1" * 999, "1" * 1000, "1" * 1001, "1" * 5000, "1" + "0" * 400, "0." + "0" * 990 + "1",
    "√" * 333 + "4", "√" * 334 + "4", "√" * 400 + "4", "π" * 499, "π" * 501, "1·" * 300 + "1",
    "1" * 998 + "²", " " * 995 + "12345", "1+" * 499 + "1", "1+" * 500 + "1", "1e" + "0" * 997,
    "(" * 20 + "1" + ")" * 20, "(" * 21 + "1" + ")" * 21, "(" * 19 + "1" + ")" * 19,
    "(" * 200 + "1" + ")" * 200, "sqrt(" * 20 + "4" + ")" * 20, "sqrt(" * 21 + "4" + ")" * 21,
    "-" * 20 + "1", "-" * 40 + "1", "-" * 41 + "1", "-" * 100 + "1", "√" * 19 + "2", "√" * 40 + "2",
    "2" + "²" * 30, "2" + "^2" * 20, "2" + "^2" * 40, "[" * 70, "{" * 70,
]
FORMULAS = [
    "px", "p_x", "2px", "2 px", "px vx", "pxvx", "px*vx", "px·vx", "px×vx", "2(px+1)", "px²",
    "px³", "√px", "√(px+vx)", "px^2", "px**2", "vx·px", "unknown", "p x", "PX", "px2", "2*px + vx",
    "r^2", "r²-px²", "sqrt(px^2+py^2+pz^2)", "px/0", "px/(vx-1)", "-px", "−px", "px−vx", "πr²",
    "2πr", "sin(px)", "px°", "px deg", "atan2(py, px)", "px,py", "px;py", "px.", ".px", "px.5",
    "1e5px", "2e", "pxe", "pxe5", "px e5", "rr", "r r", "r(r)", "sin r", "sin(r)r", "vx vy vz",
    "", " ", "\ufeffpx", "px\ufeff", "px\x00", "\x01px", "px\u00a0", "px\ud800", "(px", "px)",
]


def draw_expression(rnd, depth, symbols):
    """A random formula from the grammar (with a few glyphs and spaces), sometimes mutated."""
    if depth > 3 or rnd.random() < 0.35:
        return draw_atom(rnd, symbols)
    kind = rnd.random()
    a, b = draw_expression(rnd, depth + 1, symbols), draw_expression(rnd, depth + 1, symbols)
    space = rnd.choice(["", "", " ", "  "])
    if kind < 0.5:
        op = rnd.choice(["+", "-", "*", "/", "^", "**", "·", "×", "÷", "−", "⋅", ""])
        return a + space + op + space + b
    if kind < 0.7:
        return "(" + a + ")" + rnd.choice(["", "²", "³", "°", " deg", "^2"])
    if kind < 0.85:
        fn = rnd.choice(["sqrt", "abs", "sin", "cos", "tan", "exp", "ln", "log", "asin", "acos",
                         "atan"])
        return fn + "(" + a + ")"
    if kind < 0.92:
        return "atan2(" + a + "," + space + b + ")"
    return rnd.choice(["-", "+", "−", "√"]) + a


def draw_atom(rnd, symbols):
    r = rnd.random()
    if symbols and r < 0.3:
        return rnd.choice(symbols)
    if r < 0.45:
        return rnd.choice(["pi", "π", "√2", "2π"])
    digits = lambda n: "".join(rnd.choice("0123456789") for _ in range(n))
    mantissa = rnd.choice([digits(rnd.randint(1, 4)), digits(rnd.randint(0, 3)) + "." +
                           digits(rnd.randint(0, 4)), digits(rnd.randint(1, 20))])
    if rnd.random() < 0.3:
        mantissa += rnd.choice(["e", "E"]) + rnd.choice(["", "+", "-"]) + str(
            rnd.choice([rnd.randint(0, 30), rnd.randint(290, 330), rnd.randint(0, 400)]))
    return mantissa


HOSTILE = ["\x00", "\x01", "\x02", "\x03", "\x04", "\t", "\n", "\u00a0", "\ufeff", "\u202e",
           "\ud800", ",", ".", "e", "·", "*", "²", "√", "°", "(", ")", "\u2212", "1", " ", "π"]


def mutate(rnd, text):
    """The text with a hostile character put in, or one taken out."""
    at = rnd.randint(0, len(text))
    if text and rnd.random() < 0.3:
        return text[:max(at - 1, 0)] + text[at:]
    return text[:at] + rnd.choice(HOSTILE) + text[at:]


def corpus():
    rnd = random.Random(SEED)
    items = [{"box": "number", "text": t} for t in NUMBERS + LONG]
    items += [{"box": "formula", "text": t, "symbols": SYMBOLS} for t in FORMULAS + NUMBERS + LONG]
    # A vector: each edge case in each place, the others plain.
    for i, t in enumerate(NUMBERS):
        place = i % 3
        parts = ["1", "-2.5", "0"]
        parts[place] = t
        items.append({"box": "vector", "text": parts})
    items.append({"box": "vector", "text": ["", "", ""]})
    items.append({"box": "vector", "text": ["1", "", "3"]})
    drawn = []
    for _ in range(900):
        t = draw_expression(rnd, 0, None)
        drawn.append(mutate(rnd, t) if rnd.random() < 0.25 else t)
    items += [{"box": "number", "text": t} for t in drawn]
    for _ in range(600):
        t = draw_expression(rnd, 0, SYMBOLS)
        items.append({"box": "formula", "symbols": SYMBOLS,
                      "text": mutate(rnd, t) if rnd.random() < 0.25 else t})
    for _ in range(250):
        parts = [draw_expression(rnd, 2, None) for _ in range(3)]
        if rnd.random() < 0.25:
            k = rnd.randrange(3)
            parts[k] = mutate(rnd, parts[k])
        items.append({"box": "vector", "text": parts})
    return items


# --- The front ends

def grader(lines):
    """raygrade read-typed on (box, JSON value text) pairs: one reading each."""
    text = "".join("%s\t%s\n" % (box, value) for box, value in lines)
    r = subprocess.run([RAYGRADE, "read-typed"], input=text.encode("utf-8"),
                       capture_output=True, timeout=600)
    if r.returncode != 0:
        sys.exit("raygrade read-typed exited %d: %s" % (r.returncode, r.stderr.decode()[:400]))
    out = [json.loads(line) for line in r.stdout.decode("utf-8").split("\n")[:-1]]
    assert len(out) == len(lines), (len(out), len(lines))
    return out


def box_name(item):
    return "formula:" + ",".join(item["symbols"]) if item["box"] == "formula" else item["box"]


def as_json(value):
    # As a page (JSON.stringify) or server.py (json.dump) writes it: a lone surrogate as \udXXX.
    return json.dumps(value)


def load_server():
    path = os.path.join(REPO, "grader", "assignments", "platforms", "prairielearn_server.py")
    spec = importlib.util.spec_from_file_location("prairielearn_server", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def prairielearn(server, item):
    """What server.py hands the grader for one input, or (None, why) when it refuses it."""
    text = item["text"]
    if item["box"] == "vector":
        text = "(" + ", ".join(text) + ")"
    data = {"submitted_answers": {"answer": text}}
    try:
        typed = server._text(data, "answer")
        if item["box"] == "vector":
            return server._vector(typed), ""
        return (typed if typed != "" else None), "blank"
    except ValueError as e:
        return None, str(e)


def handout_page():
    """A handout page as `raygrade handout` writes it, for the page's own reader."""
    folder = os.path.join(WORK, "handout")
    assignment = os.path.join(REPO, "assignments", "homework-rays.json")
    r = subprocess.run([RAYGRADE, "handout", assignment, "--out", folder], capture_output=True,
                       text=True, timeout=600)
    if r.returncode != 0:
        sys.exit("raygrade handout exited %d: %s" % (r.returncode, r.stderr[:400]))
    for root, _, files in os.walk(folder):
        if "index.html" in files:
            return os.path.join(root, "index.html")
    sys.exit("no handout page in " + folder)


def ordered(bits):
    """A double's bits as an integer that counts doubles in order (-0 and +0 one apart)."""
    n = int(bits, 16)
    return -(n & 0x7FFFFFFFFFFFFFFF) - 1 if n >> 63 else n


def nan(bits):
    n = int(bits, 16)
    return (n & 0x7FF0000000000000) == 0x7FF0000000000000 and (n & 0xFFFFFFFFFFFFF) != 0


# How many doubles apart two values may be and still agree "to the last bits": the browser's C
# library (musl, in the WebAssembly reader) computes atan and atan2 within one unit in the last
# place of the native one (glibc), and a square or a product after it can make that 2 or 3.
LAST_BITS = 4


def same(a, b, formula):
    """Two readings agree: both refused, or both accepted with values at most LAST_BITS doubles
    apart; two NaNs of a formula agree. Returns 0 (disagree), 1 (bit for bit) or 2 (to the
    last bits)."""
    if a["ok"] != b["ok"]:
        return 0
    if not a["ok"]:
        return 1
    if len(a["values"]) != len(b["values"]):
        return 0
    worst = 1
    for x, y in zip(a["values"], b["values"]):
        if x == y or (formula and nan(x) and nan(y)):
            continue
        if nan(x) or nan(y) or abs(ordered(x) - ordered(y)) > LAST_BITS:
            return 0
        worst = 2
    return worst


def describe(item, reading):
    text = json.dumps(item["text"])
    text = text if len(text) < 70 else text[:67] + "..."
    verdict = ("accepted " + " ".join(reading["values"])) if reading["ok"] else (
        "refused (" + reading.get("message", "")[:60] + ")")
    return "%s %s: %s" % (item["box"], text, verdict)


def main():
    os.makedirs(WORK, exist_ok=True)
    items = corpus()
    corpus_file = os.path.join(WORK, "corpus.json")
    with open(corpus_file, "w") as f:
        json.dump(items, f)
    # The grader on the typed text.
    truth = grader([(box_name(i), as_json(i["text"])) for i in items])
    # The page: its check, and the grader on what it saves.
    page_file = os.path.join(WORK, "page.json")
    node = os.environ.get("NODE", "node")
    r = subprocess.run([node, os.path.join(REPO, "tests", "typed_corpus_page.js"), handout_page(),
                        corpus_file, page_file], capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        sys.exit("typed_corpus_page.js exited %d: %s" % (r.returncode, r.stderr[:800]))
    with open(page_file) as f:
        page = json.load(f)
    saved = grader([(box_name(i), as_json(p["saved"] if p["saved"] is not None else ""))
                    for i, p in zip(items, page)])
    # PrairieLearn: server.py's reading, then the grader on what it hands on.
    server = load_server()
    handed = [prairielearn(server, i) for i in items]
    pl = grader([(box_name(i), as_json(h if h is not None else ""))
                 for i, (h, _) in zip(items, handed)])
    for reading, (h, why) in zip(pl, handed):
        if h is None:
            reading.clear()
            reading.update({"ok": False, "message": "server.py: " + why})
    fronts = {"page check": page, "page's saved text": saved, "PrairieLearn": pl}
    counts = {name: 0 for name in fronts}
    shown = 0
    wrong = 0
    last_bit = 0
    for k, item in enumerate(items):
        agree = {n: same(readings[k], truth[k], item["box"] == "formula")
                 for n, readings in fronts.items()}
        bad = [n for n, a in agree.items() if a == 0]
        last_bit += any(a == 2 for a in agree.values())
        for n in bad:
            counts[n] += 1
        if bad:
            wrong += 1
            if shown < SHOW:
                shown += 1
                print("disagreement on " + describe(item, truth[k]) + " (grader)")
                for n in bad:
                    print("    " + n + ": " + describe(item, fronts[n][k]).split(": ", 1)[1])
    by_box = {}
    for i in items:
        by_box[i["box"]] = by_box.get(i["box"], 0) + 1
    print("typed corpus: %d inputs (%s); %d disagree with the grader (%s); %d agree to the "
          "last bits but not bit for bit" % (
              len(items), ", ".join("%d %s" % (n, b) for b, n in sorted(by_box.items())), wrong,
              ", ".join("%s %d" % (n, c) for n, c in counts.items()), last_bit))
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main())
