// The marks a check leaves in the "Your code" editor (yourcode.js): a ✓ or ✗ in the
// gutter beside each function the check ran, a click on a ✗ showing its lines of the
// report; a syntax error's ✗ on its line, the line tinted. Marks of a check made before
// the code last changed are dimmed. And which of the chapter's functions the cursor is
// in, for "check this function".
"use strict";

const kMarksGutter = "code-marks";

class EditorMarks {
  // onShow(name): a click on a function's mark.
  constructor(editor, onShow) {
    this.editor = editor;
    this.onShow = onShow;
    this.errorLine = null;
    this.editor.on("change", () => this.stale());
  }

  clear() {
    this.editor.clearGutter(kMarksGutter);
    if (this.errorLine !== null)
      this.editor.removeLineClass(this.errorLine, "background", "code-error-line");
    this.errorLine = null;
    this.editor.getWrapperElement().dataset.marks = "";
  }

  mark(line, passed, title, onClick) {
    const mark = document.createElement("button");
    mark.type = "button";
    mark.className = `code-mark ${passed ? "pass" : "fail"}`;
    mark.textContent = passed ? "✓" : "✗";
    mark.title = title;
    mark.setAttribute("aria-label", title);
    if (onClick) mark.addEventListener("click", onClick);
    this.editor.setGutterMarker(line, kMarksGutter, mark);
  }

  // A check's records (one per case: its function and status): each function's verdict
  // beside its definition in the code.
  showChecked(records, language) {
    this.clear();
    const code = this.editor.getValue();
    const byFunction = new Map();
    for (const { function: name, status } of records) {
      if (!byFunction.has(name)) byFunction.set(name, []);
      byFunction.get(name).push(status);
    }
    const shown = [];
    for (const [name, statuses] of byFunction) {
      const line = CGFS_CHECK.definitionLine(code, name, language);
      const ran = statuses.filter((status) => status !== "not written" && status !== "not checked");
      if (line < 0 || ran.length === 0) continue;
      const failed = ran.filter((status) => status !== "pass").length;
      this.mark(
        line,
        failed === 0,
        failed === 0
          ? `${name}: every case passed (${ran.length})`
          : `${name}: ${failed} of ${ran.length} cases failed: click to see them in the report`,
        failed === 0 ? null : () => this.onShow(name),
      );
      shown.push(`${name}:${failed === 0 ? "pass" : "fail"}`);
    }
    this.editor.getWrapperElement().dataset.marks = shown.join(" ");
  }

  // A message that names a line of the file (`(at FILE:LINE)`): a ✗ there, the line tinted.
  showError(message, file) {
    this.clear();
    const found = new RegExp(`\\(at ${file.replace(/[.*+?^${}()|[\]\\]/g, "\\$&")}:(\\d+)\\)`).exec(
      message,
    );
    if (!found) return;
    const line = Math.min(Number(found[1]), this.editor.lineCount()) - 1;
    this.mark(line, false, message.split("\n")[0]);
    this.errorLine = this.editor.addLineClass(line, "background", "code-error-line");
    this.editor.getWrapperElement().dataset.marks = `line ${line + 1}:error`;
  }

  stale() {
    for (const mark of this.editor.getWrapperElement().querySelectorAll(".code-mark:not(.stale)")) {
      mark.classList.add("stale");
      mark.title = `before your last change: ${mark.title}`;
    }
  }

  // The function among `names` whose definition is the last at or above the cursor.
  functionAtCursor(names, language) {
    const code = this.editor.getValue();
    const cursor = this.editor.getCursor().line;
    let best = null;
    for (const name of names) {
      const line = CGFS_CHECK.definitionLine(code, name, language);
      if (line >= 0 && line <= cursor && (best === null || line > best.line)) best = { name, line };
    }
    return best?.name ?? null;
  }
}
