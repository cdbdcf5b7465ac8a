// The checker's core for the chapter pages, bundled by scripts/site (esbuild) into
// vendor/check.js as the global CGFS_CHECK: the same judgement, messages and plan as the
// command line's (tools/check-functions/core), the account a runner gives held against
// its code's syntax, and the editor's starters.
import { heldAgainstFile, isAccount } from "../check-functions/core/account.mjs";
import { NAMES } from "../check-functions/core/names.mjs";
import {
  CASE_LIMIT,
  LOAD_LIMIT,
  functionsOf,
  sections,
  signatureFor,
} from "../check-functions/core/plan.mjs";
import { CheckError, check, stoppedLine } from "../check-functions/core/report.mjs";
import {
  carriedForward,
  definitionLine,
  fileName,
  freshStarter,
  previousChapter,
} from "./starter.mjs";

globalThis.CGFS_CHECK = {
  CASE_LIMIT,
  CheckError,
  LOAD_LIMIT,
  NAMES,
  carriedForward,
  check,
  definitionLine,
  fileName,
  freshStarter,
  functionsOf,
  heldAgainstFile,
  isAccount,
  previousChapter,
  sections,
  signatureFor,
  stoppedLine,
};
