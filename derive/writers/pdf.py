"""PDF output: the LaTeX document compiled by latexmk, safely.

latexmk runs in a private temporary folder, with shell escape off, TeX's file
access restricted to that folder (``openin_any=p``/``openout_any=p``) and a time
limit; a missing TeX installation or a TeX error is a one-line error. TeX's output
and log are read as bytes (TeX writes a line's bytes as they come, even half a UTF-8
character) and decoded leniently.
"""

from __future__ import annotations

import contextlib
import os
import re
import shutil
import signal
import subprocess
import tempfile
from pathlib import Path

from derive.errors import RenderError

TIME_LIMIT = 120  # seconds for one compilation


def build_pdf(tex_source: str, *, time_limit: float = TIME_LIMIT) -> bytes:
    """Compile ``tex_source`` (a whole document) and return the PDF's bytes."""
    latexmk = shutil.which("latexmk")
    if latexmk is None or shutil.which("pdflatex") is None:
        raise RenderError(
            "--format pdf needs TeX Live with latexmk (Debian: apt-get install latexmk "
            "texlive-latex-extra texlive-science); --format tex writes the LaTeX instead"
        )
    with tempfile.TemporaryDirectory(prefix="derive-tex-") as tmp:
        doc = Path(tmp) / "solution.tex"
        doc.write_text(tex_source, encoding="utf-8")
        env = dict(os.environ, openin_any="p", openout_any="p", shell_escape="f", TEXMFOUTPUT=tmp)
        cmd = [
            latexmk,
            "-pdf",
            "-interaction=nonstopmode",
            "-halt-on-error",
            "-file-line-error",
            "-pdflatex=pdflatex -no-shell-escape %O %S",
            doc.name,
        ]
        try:
            proc = _run(cmd, tmp, env, time_limit)
        except subprocess.TimeoutExpired:
            raise RenderError(f"LaTeX did not finish within {time_limit:g} s") from None
        pdf = Path(tmp) / "solution.pdf"
        if proc.returncode != 0 or not pdf.exists():
            log_file = Path(tmp) / "solution.log"
            log = (log_file.read_bytes() if log_file.exists() else proc.stdout).decode("utf-8", errors="replace")
            first = next(
                # "! Undefined control sequence." or, with -file-line-error, "./solution.tex:12: ..."
                # (not the banner "file:line:error style messages enabled.")
                (ln for ln in log.splitlines() if ln.startswith("!") or re.match(r"^\S+\.tex:\d+: ", ln)),
                "see the LaTeX log",
            )
            raise RenderError(f"LaTeX failed: {first.strip()}")
        return pdf.read_bytes()


def _run(cmd: list[str], cwd: str, env: dict[str, str], time_limit: float) -> subprocess.CompletedProcess[bytes]:
    """Run latexmk in its own process group; on a timeout kill the whole group, pdflatex too
    (subprocess.run would kill latexmk alone and leave pdflatex looping in a deleted folder)."""
    proc = subprocess.Popen(
        cmd,
        cwd=cwd,
        env=env,
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        start_new_session=True,
    )
    try:
        out, err = proc.communicate(timeout=time_limit)
    except BaseException:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        raise
    return subprocess.CompletedProcess(cmd, proc.returncode, out, err)
