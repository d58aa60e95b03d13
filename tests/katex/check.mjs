// Renders formulas with KaTeX and reports every one that KaTeX rejects.
//
// stdin:  a JSON list of {"tex": "...", "display": true|false, "where": "..." (optional)}
// stdout: a JSON list of errors, [] when every formula renders:
//         {"index": i, "where": ..., "tex": ..., "display": ..., "error": "KaTeX's message"}
// exit:   0 all render, 1 at least one error, 2 bad input.
//
// Options: throwOnError (a parse error is an error, not red text), strict "error"
// (LaTeX that KaTeX only accepts with a warning, e.g. unicode text in math or
// \\ in inline math, is an error too), trust false (no \href, \includegraphics...).
import katex from "katex";

function readStdin() {
  return new Promise((resolve, reject) => {
    const chunks = [];
    process.stdin.on("data", (c) => chunks.push(c));
    process.stdin.on("end", () => resolve(Buffer.concat(chunks).toString("utf8")));
    process.stdin.on("error", reject);
  });
}

let items;
try {
  items = JSON.parse(await readStdin());
  if (!Array.isArray(items)) throw new Error("expected a JSON list");
} catch (err) {
  process.stderr.write(`check.mjs: bad input: ${err.message}\n`);
  process.exit(2);
}

const errors = [];
items.forEach((item, index) => {
  const tex = typeof item === "string" ? item : item.tex;
  const display = typeof item === "object" && item !== null && Boolean(item.display);
  const where = typeof item === "object" && item !== null ? item.where ?? null : null;
  if (typeof tex !== "string") {
    errors.push({ index, where, tex, display, error: "not a string" });
    return;
  }
  try {
    katex.renderToString(tex, {
      displayMode: display,
      throwOnError: true,
      strict: "error",
      trust: false,
      output: "htmlAndMathml",
    });
  } catch (err) {
    errors.push({ index, where, tex, display, error: String(err && err.message ? err.message : err) });
  }
});

process.stdout.write(JSON.stringify(errors, null, 2) + "\n");
process.exit(errors.length ? 1 : 0);
