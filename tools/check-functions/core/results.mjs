// A check's results as Gradescope's autograder results.json (its documented "Output
// format": gradescope-autograders.readthedocs.io, "Autograder Specifications"), the
// format a course's autograder hands back: one test per case, passed or failed, a point
// each, its message as the test's output; what Gradescope has no field for (the case's
// own status, what it catches, returned against expected, what the student's code
// printed) in the test's extra_data, which the format keeps for the course.
// tests/check-functions/gradescope-results.schema.json is that specification as a JSON
// Schema; a test validates our files against it.

const PRINTED_LIMIT = 4000;

// The test's output: the message, and what the student's code printed, marked as theirs.
function outputOf(each) {
  const parts = [each.status === "pass" ? "passed" : `${each.status}: ${each.message}`];
  if (each.status !== "pass" && each.catches) parts.push(`this case catches: ${each.catches}`);
  if (each.printed)
    parts.push(
      `your code printed${each.printedCut ? " (cut short)" : ""}:\n${each.printed.slice(0, PRINTED_LIMIT)}`,
    );
  if (each.rerun) parts.push(`alone: ${each.rerun}`);
  return parts.join("\n");
}

// result: check()'s { records, verdict, lines }; about: { chapter, file, language,
// seconds, report, notes }.
export function gradescopeResults(result, { chapter, file, language, seconds, report, notes }) {
  const tests = result.records.map((each) => ({
    name: `${each.function}, case ${each.case} of ${each.caseFile}`,
    number: `${each.caseFile.slice(0, 2)}.${each.function}.${each.case}`,
    score: each.status === "pass" ? 1 : 0,
    max_score: 1,
    status: each.status === "pass" ? "passed" : "failed",
    output: outputOf(each),
    output_format: "text",
    tags: [each.function, each.caseFile.replace(/\.json$/, "")],
    extra_data: {
      function: each.function,
      case_file: each.caseFile,
      case: each.case,
      status: each.status,
      message: each.message,
      catches: each.catches,
      returned: each.returned ?? null,
      expected: each.expected,
      printed: each.printed ?? "",
      printed_by: "the student's code",
      printed_cut: each.printedCut ?? false,
      ...(each.rerun ? { rerun: each.rerun } : {}),
    },
  }));
  return {
    score: tests.reduce((sum, test) => sum + test.score, 0),
    execution_time: Math.round(seconds),
    output: report,
    output_format: "text",
    extra_data: {
      chapter,
      file,
      language,
      verdict: result.verdict,
      notes,
      counts: Object.fromEntries(
        ["pass", "fail", "error", "timeout", "not written", "not checked"].map((status) => [
          status,
          result.records.filter((each) => each.status === status).length,
        ]),
      ),
    },
    tests,
  };
}
