"""A self-contained HTML page: KaTeX for the mathematics, with no network at view time.

KaTeX (MIT licence) is vendored in ``derive/vendor/katex``. Where Node.js is on
the machine the formulas are typeset when the page is written, so the page
needs no script at all; otherwise the page carries KaTeX's script inline and
typesets itself when opened. Either way its fonts are inlined as data URIs.
"""

from __future__ import annotations

import base64
import json
import re
import shutil
import subprocess
from functools import cache
from pathlib import Path

VENDOR = Path(__file__).resolve().parent.parent / "vendor" / "katex"
NODE_TIME_LIMIT = 60

_NODE_SCRIPT = r"""
const katex = require(process.argv[1]);
let input = "";
process.stdin.on("data", (d) => (input += d));
process.stdin.on("end", () => {
  const out = JSON.parse(input).map(([tex, display]) => {
    try {
      return katex.renderToString(tex, { displayMode: display, throwOnError: true, strict: "ignore", trust: false });
    } catch (e) {
      return null;
    }
  });
  process.stdout.write(JSON.stringify(out));
});
"""


@cache
def katex_css() -> str:
    """KaTeX's stylesheet with its woff2 fonts inlined (other font formats dropped)."""
    css = (VENDOR / "katex.min.css").read_text(encoding="utf-8")

    def inline(match: re.Match[str]) -> str:
        name = match.group(1)
        data = base64.b64encode((VENDOR / "fonts" / f"{name}.woff2").read_bytes()).decode("ascii")
        return f'src:url(data:font/woff2;base64,{data}) format("woff2")'

    return re.sub(r'src:url\(fonts/([A-Za-z0-9_-]+)\.woff2\) format\("woff2"\)[^;}]*', inline, css)


@cache
def katex_script() -> str:
    """KaTeX's script, for a page that typesets itself."""
    return (VENDOR / "katex.min.js").read_text(encoding="utf-8").replace("</script", "<\\/script")


def render_math(items: list[tuple[str, bool]]) -> list[str] | None:
    """Each (tex, display) typeset as HTML by KaTeX under Node.js; None without Node."""
    node = shutil.which("node")
    if node is None or not items:
        return None if node is None else []
    try:
        proc = subprocess.run(
            [node, "-e", _NODE_SCRIPT, str(VENDOR / "katex.min.js")],
            input=json.dumps(items),
            capture_output=True,
            text=True,
            timeout=NODE_TIME_LIMIT,
            check=False,
        )
    except (OSError, subprocess.TimeoutExpired):
        return None
    if proc.returncode != 0:
        return None
    out = json.loads(proc.stdout)
    if len(out) != len(items) or any(x is None for x in out):
        return None
    return out
