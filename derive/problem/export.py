"""The schema for people and editors: the field tables of ``docs/problem-format.md`` and
JSON Schema files (``docs/derive-problem.schema.json``, ``docs/derive-answers.schema.json``)
that TOML editors such as Taplo use to complete and check a file as it is typed.

Both are written from :mod:`derive.problem.schema`, so they cannot drift from what
derive checks: ``python -m derive.problem.export`` rewrites them, and a test fails
when they are out of date.
"""

from __future__ import annotations

import json
import re
import sys
from pathlib import Path
from typing import Any

from derive.problem.schema import ANSWERS, BODY, CHAIN, GEOMETRY, NAME_PATTERN, PROBLEM, RANGE, STAGES, Field, Table

SCHEMA_URL = "http://json-schema.org/draft-07/schema#"
#: Generated blocks of the docs, by name: ``<!-- generated: NAME -->`` … ``<!-- end generated -->``.
_BLOCK = re.compile(r"(<!-- generated: ([\w-]+) -->\n)(.*?)(<!-- end generated -->)", re.S)


# ---------------------------------------------------------------- JSON Schema


def field_schema(f: Field) -> dict[str, Any]:
    """The JSON Schema of one field (with its meaning as the description editors show)."""
    out = _type_schema(f)
    text = f.meaning + (f" Default: {f.default}." if f.default else "")
    out["description"] = text.replace("`", "")
    out["markdownDescription"] = text
    return out


def _type_schema(f: Field) -> dict[str, Any]:
    t = f.type
    if t in ("text", "unit", "line"):
        out: dict[str, Any] = {"type": "string"}
        if f.max_length:
            out["maxLength"] = f.max_length
        if t == "line":
            out["minLength"] = 1
        return out
    if t == "boolean":
        return {"type": "boolean"}
    if t == "integer":
        return {"type": "integer", "minimum": f.minimum, "maximum": f.maximum}
    if t == "number":
        return {"type": "number", "minimum": -1e30, "maximum": 1e30}
    if t == "choice":
        return {"type": "string", "enum": list(f.choices)}
    if t == "tolerance":
        return {
            "anyOf": [
                {"type": "number", "exclusiveMinimum": 0, "exclusiveMaximum": 1},
                {"type": "string", "pattern": r"^\s*(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d{1,2})?\s*%?\s*$"},
            ]
        }
    if t in ("value", "expression"):
        return {"type": ["number", "string"], "minimum": -1e30, "maximum": 1e30, "maxLength": f.max_length or 500}
    if t == "name":
        return {"type": "string", "pattern": NAME_PATTERN}
    if t == "names":
        array = {"type": "array", "items": {"type": "string"}, "maxItems": f.max_items}
        return {"anyOf": [{"type": "string"}, array]} if f.also == "name" else array
    if t == "table":
        assert f.table is not None
        return table_schema(f.table)
    assert t == "list"
    out = {"type": "array", "minItems": f.min_items}
    if f.max_items is not None:
        out["maxItems"] = f.max_items
    if f.items is not None:
        out["items"] = field_schema(f.items) if f.items.type != "table" else _item_table(f.items)
        if f.also == "one":
            return {"anyOf": [out["items"], out]}
    return out


def _item_table(f: Field) -> dict[str, Any]:
    assert f.table is not None
    return table_schema(f.table)


def table_schema(table: Table) -> dict[str, Any]:
    """The JSON Schema of a table: its fields (closed), or its entries (an open table)."""
    out: dict[str, Any] = {"type": "object", "description": table.meaning}
    if table.by:
        out["required"] = [table.by]
        out["properties"] = {f.name: field_schema(f) for f in table.fields}
        out["allOf"] = [
            {"if": {"properties": {table.by: {"const": name}}}, "then": table_schema(case)}
            for name, case in table.cases.items()
        ]
        return out
    if table.fields:
        out["properties"] = {f.name: field_schema(f) for f in table.fields}
        out["additionalProperties"] = False
        required = [f.name for f in table.fields if f.required]
        if required:
            out["required"] = required
    if table.keys is not None:
        out["additionalProperties"] = field_schema(table.keys)
        if table.key_pattern:
            out["propertyNames"] = {"pattern": table.key_pattern}
        if table.max_keys:
            out["maxProperties"] = table.max_keys
    if table.forms:
        out["oneOf"] = [{"required": list(form)} for form in table.forms]
    return out


def problem_schema() -> dict[str, Any]:
    """The JSON Schema of a problem file: a single impact, or a chain (``kind = "chain"``)."""
    return {
        "$schema": SCHEMA_URL,
        "$id": "https://derive.invalid/derive-problem.schema.json",
        "title": "derive problem file",
        "description": "A central-impact problem (or a chain of stages) for derive; see docs/problem-format.md.",
        "type": "object",
        "if": {"properties": {"kind": {"const": "chain"}}, "required": ["kind"]},
        "then": table_schema(CHAIN),
        "else": table_schema(PROBLEM),
    }


def answers_schema() -> dict[str, Any]:
    """The JSON Schema of an answers file (``derive check --answers FILE``)."""
    return {
        "$schema": SCHEMA_URL,
        "$id": "https://derive.invalid/derive-answers.schema.json",
        "title": "derive answers file",
        **table_schema(ANSWERS),
    }


# ---------------------------------------------------------------- Markdown tables


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def fields_table(table: Table) -> str:
    """A Markdown table of ``table``'s fields: field, type, required, meaning."""
    rows = ["| field | type | required | meaning |", "|" + " --- |" * 4]
    for f in table.fields:
        kind = _type_words(f)
        meaning = f.meaning + (f" (default: {f.default})" if f.default else "")
        cells = [f"`{f.name}`", kind, "yes" if f.required else "no", meaning]
        rows.append("| " + " | ".join(_cell(c) for c in cells) + " |")
    return "\n".join(rows) + "\n"


def _type_words(f: Field) -> str:
    if f.type == "choice":
        return ", ".join(f"`{c}`" for c in f.choices)
    if f.type == "integer":
        return f"whole number {f.minimum:g}–{f.maximum:g}"
    if f.type == "table":
        return "table"
    if f.type == "list":
        n = f" of {f.min_items}" if f.min_items == f.max_items else ""
        return f"list{n}"
    return {
        "text": "text",
        "line": f"text (≤ {f.max_length})",
        "boolean": "`true` / `false`",
        "value": "number or text",
        "expression": "expression",
        "name": "name",
        "names": "list of names",
        "unit": "unit",
        "tolerance": "number or text",
        "number": "number",
    }[f.type]


def stages_table() -> str:
    """The Markdown table of the chain stage types: each type's fields and what it finds."""
    rows = ["| `type` | fields (* required) | result |", "| --- | --- | --- |"]
    for name, table in STAGES.items():
        own = [f for f in table.fields if f.name not in ("type", "title")]
        shown = ", ".join(f"`{f.name}`" + ("*" if f.required else "") for f in own)
        rows.append(f"| `{name}` | {_cell(shown)} | {_cell(table.meaning)} |")
    return "\n".join(rows) + "\n"


def stage_fields_tables() -> str:
    """One Markdown table per stage type: each field's type, whether required, and meaning."""
    out = []
    for name, table in STAGES.items():
        if name == "impact":
            continue
        out.append(f"**`{name}`**: {table.meaning}\n\n{fields_table(table)}")
    return "\n".join(out)


BLOCKS = {
    "problem-fields": lambda: fields_table(PROBLEM),
    "body-fields": lambda: fields_table(BODY),
    "geometry-fields": lambda: fields_table(GEOMETRY),
    "vary-fields": lambda: fields_table(RANGE),
    "chain-fields": lambda: fields_table(CHAIN),
    "stage-types": stages_table,
    "stage-fields": stage_fields_tables,
    "answers-fields": lambda: fields_table(ANSWERS),
}


def update_docs(text: str) -> str:
    """``text`` (a Markdown page) with every generated block written anew from the schema."""

    def block(m: re.Match[str]) -> str:
        return m.group(1) + BLOCKS[m.group(2)]() + m.group(4)

    return _BLOCK.sub(block, text)


def outputs(root: Path) -> dict[Path, str]:
    """Every file written from the schema, under the project folder ``root``, with its content."""
    docs = root / "docs"
    out = {
        docs / "derive-problem.schema.json": json.dumps(problem_schema(), indent=2, ensure_ascii=False) + "\n",
        docs / "derive-answers.schema.json": json.dumps(answers_schema(), indent=2, ensure_ascii=False) + "\n",
    }
    for page in ("problem-format.md", "checking.md"):
        path = docs / page
        if path.exists():
            out[path] = update_docs(path.read_text(encoding="utf-8"))
    return out


def main(argv: list[str] | None = None) -> int:
    """``python -m derive.problem.export [ROOT]``: rewrite the docs' tables and the JSON Schema files."""
    args = sys.argv[1:] if argv is None else argv
    root = Path(args[0]) if args else Path.cwd()
    for path, text in outputs(root).items():
        if not path.exists() or path.read_text(encoding="utf-8") != text:
            path.write_text(text, encoding="utf-8")
            print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
