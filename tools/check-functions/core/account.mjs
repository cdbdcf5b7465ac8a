// The account a runner gives of a student's file (which book functions it defines, the
// parameters each takes, whether its body is still empty), held against what the file
// says of itself, read without running any of it: by the checker, before the runner
// starts (source_facts.js), or by a chapter page's worker before the reader's code
// runs in it. A runner whose account differs cannot leave cases unrun: a function it
// hides or describes otherwise fails, and an empty body is the file's to tell.

// Whether a runner's answer to loading the file is an account of it: which functions it
// defines (`functions`, by name) and the names defined (`defined`). Anything else is not.
export function isAccount(facts) {
  return (
    !!facts &&
    typeof facts === "object" &&
    !!facts.functions &&
    typeof facts.functions === "object" &&
    Array.isArray(facts.defined)
  );
}

// The runner's account of the wanted functions, each held against the file's: `defined`
// maps a name to { count, required, more, empty }; null when the file could not be read
// (the runner says why it does not load).
export function heldAgainstFile(facts, defined, wanted) {
  if (!defined) return facts;
  for (const name of wanted) {
    const declared = defined.get(name);
    if (!declared) continue;
    const told = facts.functions[name];
    if (!told) {
      facts.functions[name] = {
        forged: `your file defines ${name}, but the process it ran in said it does not`,
      };
    } else if (
      told.parameters &&
      (told.parameters.names.length !== declared.count ||
        told.parameters.required !== declared.required)
    ) {
      facts.functions[name] = {
        forged:
          `the process your code ran in described ${name} otherwise than your file does ` +
          `(${declared.count} parameters there, ${told.parameters.names.length} in its account)`,
      };
    } else {
      told.empty = declared.empty;
    }
  }
  return facts;
}
