"""Seed corpora for the fuzz harnesses, from the case files in tests/cases.

Usage: python make_seeds.py OUTPUT_DIR  (writes OUTPUT_DIR/{mdpa,parameters,expression}/, one file
per seed, named by its content hash so repeated runs do not duplicate seeds).
"""

import hashlib
import json
import re
import sys
from pathlib import Path

CASES = Path(__file__).resolve().parents[1] / "cases"
# Small files only: libFuzzer mutates faster on short inputs, and the small cases already hold
# every block type.
MAX_BYTES = 16 * 1024
EXPRESSION = re.compile(r"^[-+*/^().,0-9a-zA-Z_ <>=?:&|!]+$")
EXPRESSION_NAMES = re.compile(r"\b(t|x|y|z|X|Y|Z|sin|cos|sqrt|exp|pi)\b")
# The case files use only linear ramps; these reach muparser's functions, operators and ternary.
EXTRA_EXPRESSIONS = [
    "sqrt(x**2+y**2)*sin(t)",
    "pow(X,2)+exp(-t)*cos(pi*Y)",
    "x>0 ? 1e-3*t : -abs(z)",
    "min(x,y,z)+max(X,Y)+sum(1,2,t)/avg(x,t)",
    "log(1+t)+ln(e)+log10(100)+log2(8)+tanh(x)+atan2(y,x)",
    "(x<=1 && t>=0) || !(y!=0)",
    "rint(sign(-t)*2.5)-asin(0.5)+acosh(2)",
]


def write(folder: Path, text: str) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    data = text.encode()
    (folder / hashlib.sha1(data).hexdigest()).write_bytes(data)


def strings_in(value):
    if isinstance(value, str):
        yield value
    elif isinstance(value, dict):
        for item in value.values():
            yield from strings_in(item)
    elif isinstance(value, list):
        for item in value:
            yield from strings_in(item)


def main(output: Path) -> None:
    for path in sorted(CASES.rglob("*.mdpa")):
        if path.stat().st_size <= MAX_BYTES:
            write(output / "mdpa", path.read_text(errors="replace"))
    expressions = set()
    for path in sorted(CASES.rglob("*.json")):
        if path.stat().st_size > MAX_BYTES:
            continue
        text = path.read_text(errors="replace")
        write(output / "parameters", text)
        try:
            document = json.loads(text)
        except ValueError:
            continue
        expressions.update(
            s for s in strings_in(document) if EXPRESSION.match(s) and EXPRESSION_NAMES.search(s)
        )
    for expression in sorted(expressions) + EXTRA_EXPRESSIONS:
        write(output / "expression", expression)


if __name__ == "__main__":
    main(Path(sys.argv[1]))
