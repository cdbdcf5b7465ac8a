// What a student's file says of itself, read without running any of it: the functions it
// defines at its top level and the parameters each takes (Python's own parser, ast, in a
// process of its own; acorn for JavaScript, a page's scripts included). The checker holds
// the account the student's process gives of itself against it, so that no process can
// hide a function it has ("not written yet") or give one fewer parameters than it takes
// (another listing's cases) to leave cases unrun.
"use strict";

const { execFileSync } = require("child_process");
const fs = require("fs");
const path = require("path");

const PYTHON = `
import ast, json, sys
with open(sys.argv[1], encoding="utf-8", errors="replace") as source:
    tree = ast.parse(source.read())
found = {}
for node in tree.body:
    if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
        a = node.args
        positional = len(a.posonlyargs) + len(a.args)
        found[node.name] = {"count": positional, "required": positional - len(a.defaults), "more": a.vararg is not None}
print(json.dumps(found))
`;

function pythonFunctions(file, python) {
  const text = execFileSync(python, ["-I", "-c", PYTHON, file], { encoding: "utf8", timeout: 20000, stdio: ["ignore", "pipe", "ignore"] });
  return new Map(Object.entries(JSON.parse(text)));
}

function parameters(node) {
  let required = 0, optional = false, more = false, count = 0;
  for (const param of node.params) {
    if (param.type === "RestElement") { more = true; continue; }
    count += 1;
    if (param.type === "AssignmentPattern") optional = true;
    if (!optional) required += 1;
  }
  return { count, required, more };
}

function jsFunctions(file, nodePath) {
  const dir = nodePath.split(path.delimiter).find((each) => fs.existsSync(path.join(each, "acorn", "package.json")));
  const acorn = require(path.join(dir, "acorn"));
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
    let program;
    for (const sourceType of ["script", "module"]) {
      try {
        program = acorn.parse(code, { ecmaVersion: "latest", sourceType, allowHashBang: true });
        break;
      } catch {
        // the other kind, or not ours to judge (the runner says the syntax error)
      }
    }
    for (let node of program?.body ?? []) {
      if (node.type === "ExportNamedDeclaration" && node.declaration) node = node.declaration;
      if (node.type === "FunctionDeclaration" && node.id) found.set(node.id.name, parameters(node));
      if (node.type !== "VariableDeclaration") continue;
      for (const each of node.declarations) {
        if (each.id.type === "Identifier" && /^(FunctionExpression|ArrowFunctionExpression)$/.test(each.init?.type)) {
          found.set(each.id.name, parameters(each.init));
        }
      }
    }
  }
  return found;
}

// The functions `file` defines at its top level: name -> { count, required, more }; null
// when it cannot be read (the runner says why).
function definedFunctions(file, language, { python, nodePath }) {
  try {
    return language === "python" ? pythonFunctions(file, python) : jsFunctions(file, nodePath);
  } catch {
    return null;
  }
}

// The runner's account of the wanted functions, each held against the file: a function
// the file defines that the account lacks, or describes with other parameters, is marked
// forged, and fails.
function heldAgainstFile(facts, defined, wanted) {
  if (!defined) return facts;
  for (const name of wanted) {
    const declared = defined.get(name);
    if (!declared) continue;
    const told = facts.functions[name];
    if (!told) {
      facts.functions[name] = { forged: `your file defines ${name}, but the process it ran in said it does not` };
    } else if (told.parameters && (told.parameters.names.length !== declared.count || told.parameters.required !== declared.required)) {
      facts.functions[name] = { forged: `the process your code ran in described ${name} otherwise than your file does ` +
        `(${declared.count} parameters there, ${told.parameters.names.length} in its account)` };
    }
  }
  return facts;
}

module.exports = { definedFunctions, heldAgainstFile };
