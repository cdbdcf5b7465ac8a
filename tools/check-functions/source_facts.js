// What a student's file says of itself, read without running any of it: the functions it
// defines at its top level, the parameters each takes and whether its body is still
// empty (Python's own parser, ast, in a process of its own, through python_runner.py
// --declared; acorn for JavaScript, a page's scripts included). The checker holds the
// account the student's process gives of itself against it (core/account.mjs).
"use strict";

const { execFileSync } = require("child_process");
const fs = require("fs");
const path = require("path");

function pythonFunctions(file, python) {
  const runner = path.join(__dirname, "runners", "python_runner.py");
  const text = execFileSync(python, ["-I", "-B", runner, "--declared", file], {
    encoding: "utf8",
    timeout: 20000,
    stdio: ["ignore", "pipe", "ignore"],
  });
  return new Map(Object.entries(JSON.parse(text)));
}

async function jsFunctions(file, nodePath) {
  const dir = nodePath
    .split(path.delimiter)
    .find((each) => fs.existsSync(path.join(each, "acorn", "package.json")));
  const acorn = require(path.join(dir, "acorn"));
  const { declaredFunctions } = await import("./runners/js_core.mjs");
  const source = fs.readFileSync(file, "utf8");
  let codes = [source];
  if (/\.html?$/i.test(file)) {
    const pattern = /<script\b([^>]*)>([\s\S]*?)<\/script\s*>/gi;
    codes = [];
    for (let match; (match = pattern.exec(source)) !== null;) {
      if (!/\bsrc\s*=/i.test(match[1])) codes.push(match[2]);
    }
  }
  const found = new Map();
  for (const code of codes) {
    for (const sourceType of ["script", "module"]) {
      try {
        const program = acorn.parse(code, {
          ecmaVersion: "latest",
          sourceType,
          allowHashBang: true,
        });
        for (const [name, each] of declaredFunctions(program)) found.set(name, each);
        break;
      } catch {
        // the other kind, or not ours to judge (the runner says the syntax error)
      }
    }
  }
  return found;
}

// The functions `file` defines at its top level: name -> { count, required, more, empty };
// null when it cannot be read (the runner says why).
async function definedFunctions(file, language, { python, nodePath }) {
  try {
    return language === "python"
      ? pythonFunctions(file, python)
      : await jsFunctions(file, nodePath);
  } catch {
    return null;
  }
}

module.exports = { definedFunctions };
