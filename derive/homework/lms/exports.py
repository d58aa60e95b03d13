"""What ``derive variants --moodle/--prairielearn`` writes, built in memory first."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from derive.errors import InputError
from derive.homework.lms.files import Exports, folder_exports
from derive.homework.lms.grading import resolve_result
from derive.homework.lms.mistake_model import MistakeModel
from derive.homework.lms.moodle import moodle_xml
from derive.homework.lms.pl import prairielearn_files
from derive.homework.lms.stack import stack_xml
from derive.problem import Problem

if TYPE_CHECKING:
    from derive.homework.variants import Compiled


def build_exports(
    problem: Problem,
    *,
    count: int,
    seed: int,
    digits: int | None = None,
    result: str | None = None,
    moodle: str | None = None,
    prairielearn: str | None = None,
    stack: str | None = None,
    compiled: Compiled | None = None,
) -> Exports:
    """What ``derive variants --moodle/--prairielearn/--stack`` writes, built in memory first
    so that a bad ``--result`` writes nothing. The variants are those ``write_variants``
    draws for the same file and seed (``compiled``: the problem compiled already, as
    ``derive variants`` does once for both)."""
    from derive.homework.variants import compile_problem, draw

    for option, path in (("--moodle", moodle), ("--stack", stack)):
        if path:
            _check_file(path, option)
    if prairielearn and Path(prairielearn).exists() and not Path(prairielearn).is_dir():
        raise InputError("exists and is not a folder", where=prairielearn, field="--prairielearn")
    compiled = compiled or compile_problem(problem)
    chosen = draw(compiled, count, seed)
    asked = result
    result = resolve_result(compiled, chosen, result, digits)
    model = MistakeModel(compiled)  # shared: each variant's mistakes are worked out once
    out = Exports([], [])
    if moodle:
        out.files.append((Path(moodle), moodle_xml(compiled, chosen, result=result, digits=digits, model=model)))
        out.folders.append(Path(moodle).parent)
    if stack:
        out.files.append((Path(stack), stack_xml(compiled, chosen, result=asked, digits=digits, model=model)))
        out.folders.append(Path(stack).parent)
    if prairielearn:
        files = prairielearn_files(compiled, chosen, result=result, digits=digits, seed=seed, model=model)
        out.trees = folder_exports(prairielearn, files).trees
    return out


def _check_file(path: str, option: str) -> None:
    """An export file's path, checked before anything is written: no file on the way to it,
    not a folder (its folder is made when the files are written: it may be the -o folder)."""
    parent = Path(path).parent
    for folder in (parent, *parent.parents):
        if folder.exists() and not folder.is_dir():
            raise InputError("a folder on the way is a file", where=str(folder), field=option)
    if Path(path).is_dir():
        raise InputError("is a folder, not a file", where=path, field=option)
