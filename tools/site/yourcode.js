// The "Your code" panel of a chapter's page: the reader writes the chapter's functions
// (JavaScript or Python) in an editor (CodeMirror 5, Debian's libjs-codemirror), checks
// them against the chapter's cases with the command line's judgement and messages
// (vendor/check.js, the checker's core), and draws a figure with them, compared with
// ours as cgfs-compare compares (the comparison library in the chapter's WebAssembly,
// figures_worker.js). The reader's code runs in a Web Worker of its own
// (code_runner.js). It is kept in the browser's local storage, per chapter and
// language; a chapter not written yet opens on the reader's previous chapter carried
// forward, or on a starter. All of it inside one function: the page's other scripts
// (chapter.js) have names of their own in the page's global scope.
(() => {
  "use strict";

  const kDrawLimit = 300; // seconds a figure drawn with the reader's functions may take

  const yourCode = {
    chapter: document.getElementById("live").dataset.chapter,
    title: document.getElementById("your-code").dataset.title,
    files: CGFS_CASES,
    drawings: CGFS_DRAWINGS[document.getElementById("live").dataset.chapter] ?? {},
    editor: null,
    language: "javascript",
    file: "", // the name the report gives the code: the file opened, or the chapter's
    running: null, // the PageRunner of a check under way
    marks: null, // the EditorMarks a check leaves (editor_marks.js)
    figures: null, // a FiguresWorker for ours and the comparison, made on the first draw
    comparison: null, // the ComparisonView of a draw (compare_view.js)
    lastCheck: null, // { code, failed } of the last check that ran to its end
  };

  const $ = (id) => document.getElementById(id);
  const StorageKey = (chapter, language) => `cgfs-code:${chapter}:${language}`;
  // Which functions of the chapter passed the last full check: read by the index (index.js).
  const ProgressKey = (chapter) => `cgfs-progress:${chapter}`;
  const kTypingPause = 1000; // milliseconds without typing before "check as I type" checks
  const kMostCode = 1 << 20; // bytes of code a file or a link may bring (a chapter is a few KB)
  // A link's code (#code=LANGUAGE:DEFLATED-BASE64URL), read before chapter.js rewrites the
  // address for the figure shown.
  const kLinked = /^#code=(javascript|python):([A-Za-z0-9_-]+)$/.exec(location.hash);

  function Stored(key) {
    try {
      return localStorage.getItem(key);
    } catch {
      return null; // storage refused (a private window, a page opened from a file): nothing kept
    }
  }

  function Store(key, value) {
    try {
      if (value === null) localStorage.removeItem(key);
      else localStorage.setItem(key, value);
    } catch {
      $("code-status").textContent =
        "Your browser keeps nothing for this page: Download keeps your code.";
    }
  }

  // What the editor opens on: the reader's code of this chapter, or of the chapter before
  // carried forward, or a starter.
  function OpeningCode(language) {
    const { chapter, files, title } = yourCode;
    const stored = Stored(StorageKey(chapter, language));
    if (stored !== null) return stored;
    const previous = CGFS_CHECK.previousChapter(chapter, files);
    const before = previous && Stored(StorageKey(previous, language));
    return before
      ? CGFS_CHECK.carriedForward(chapter, before, files, language, title)
      : CGFS_CHECK.freshStarter(chapter, files, language, title);
  }

  function ShowCode(language, code, file) {
    yourCode.language = language;
    yourCode.file =
      file ??
      Stored(`${StorageKey(yourCode.chapter, language)}:file`) ??
      CGFS_CHECK.fileName(yourCode.chapter, language);
    $("code-language").value = language;
    $("code-auto-label").hidden = language !== "javascript";
    $("code-file").textContent = yourCode.file;
    yourCode.editor.setOption("mode", language);
    // Python's blocks are 4 spaces (PEP 8, and the starter's), JavaScript's 2 (the demos').
    yourCode.editor.setOption("indentUnit", language === "python" ? 4 : 2);
    yourCode.editor.setValue(code);
    yourCode.editor.clearHistory();
  }

  function Save() {
    Store(StorageKey(yourCode.chapter, yourCode.language), yourCode.editor.getValue());
  }

  function Busy(what) {
    $("code-panel").dataset.busy = what ?? "";
    for (const id of [
      "code-check",
      "code-check-one",
      "code-draw",
      "code-language",
      "code-open-button",
      "code-start-over",
    ]) {
      $(id).disabled = what !== null;
    }
    $("code-stop").hidden = what === null;
    if (what === null) {
      ShowFunctionAtCursor(); // enabled only in one of the chapter's functions
      RefillWorkers();
    }
  }

  function Status(text) {
    $("code-status").textContent = text;
  }

  // How far Python's start has come (0 to 1), on its bar; the bar gone once it has started.
  function PythonStarting(fraction) {
    $("code-python-start").hidden = fraction >= 1;
    $("code-python-start").value = fraction;
    if (fraction < 1) Status(`starting Python (Pyodide)… ${Math.round(fraction * 100)} %`);
    else if ($("code-status").textContent.startsWith("starting Python")) Status("Python is ready.");
  }

  // The report, a line to a span: a function's first line names it (data-function), for
  // the editor's marks to show.
  function ShowReport(lines) {
    const names = new Set(
      CGFS_CHECK.functionsOf(CGFS_CHECK.sections(yourCode.chapter, yourCode.files)),
    );
    $("code-report").replaceChildren(
      ...lines.flatMap((line, i) => {
        const span = document.createElement("span");
        span.textContent = line;
        const name = /^ {2}(\w+) /.exec(line)?.[1];
        if (names.has(name)) span.dataset.function = name;
        return i === 0 ? [span] : ["\n", span];
      }),
    );
  }

  // A function's first failed lines in the report, scrolled into view and lit.
  function ShowInReport(name) {
    const line =
      [...$("code-report").querySelectorAll("span[data-function]")].find(
        (span) =>
          span.dataset.function === name && /FAILED|raised|ran out|did not/.test(span.textContent),
      ) ?? $("code-report").querySelector(`span[data-function="${name}"]`);
    if (!line) return;
    line.scrollIntoView({ block: "center", behavior: "smooth" });
    line.classList.remove("lit");
    void line.offsetWidth; // restarts the light's animation
    line.classList.add("lit");
  }

  // The chapter's function the cursor is in, for "check this function".
  function FunctionAtCursor() {
    const names = CGFS_CHECK.functionsOf(CGFS_CHECK.sections(yourCode.chapter, yourCode.files));
    return yourCode.marks.FunctionAtCursor(names, yourCode.language);
  }

  function ShowFunctionAtCursor() {
    const name = FunctionAtCursor();
    $("code-check-one").textContent = name ? `Check ${name}` : "Check one function";
    $("code-check-one").title = name
      ? `${name}'s cases alone (Shift+Ctrl+Enter), as --function ${name} does`
      : "Put the cursor in one of the chapter's functions to check it alone";
    $("code-check-one").dataset.function = name ?? "";
    if (!$("code-panel").dataset.busy) $("code-check-one").disabled = !name;
  }

  // Check: the chapter's cases, and those of the chapters it keeps, on the reader's code;
  // only: one function's cases alone (as --function NAME).
  async function Check(only = null) {
    const { chapter, files, language } = yourCode;
    if (yourCode.running || $("code-panel").dataset.busy) return;
    Save();
    Busy("check");
    $("code-report").textContent = "";
    $("code-report").dataset.failed = "";
    yourCode.marks.Clear();
    const list = CGFS_CHECK.sections(chapter, files).map((section) =>
      only === null
        ? section
        : { ...section, entries: section.entries.filter((entry) => entry.function === only) },
    );
    const totalCases = list
      .flatMap((section) => section.entries)
      .reduce((n, entry) => n + entry.cases.length, 0);
    const runner = new PageRunner({
      language,
      code: yourCode.editor.getValue(),
      file: yourCode.file,
      timeLimit: CGFS_CHECK.CASE_LIMIT,
      totalCases,
      onStatus: Status,
      onStarting: PythonStarting,
    });
    yourCode.running = runner;
    const start = performance.now();
    try {
      const { lines, failed, records } = await CGFS_CHECK.check({
        chapter,
        files,
        runner,
        file: yourCode.file,
        only: only === null ? null : { function: only },
      });
      ShowReport(lines);
      yourCode.marks.ShowChecked(records, language);
      $("code-report").dataset.failed = failed ? "yes" : "no";
      const checked = (Date.now() - runner.started) / 1000;
      if (runner.ended && yourCode.running !== runner) {
        Status(`Stopped after ${checked.toFixed(1)} s: the cases not run are not checked.`);
        return;
      }
      if (only === null) {
        yourCode.lastCheck = { code: runner.code, failed };
        KeepProgress(records, language);
      }
      Status(
        `${failed ? "Something to fix" : "Every case passed"}: checked in ${checked.toFixed(2)} s` +
          (language === "python"
            ? ` (${((performance.now() - start) / 1000).toFixed(1)} s with starting Python)`
            : ""),
      );
    } catch (error) {
      $("code-report").textContent =
        error instanceof CGFS_CHECK.CheckError
          ? error.message
          : `The check could not run: ${error.message ?? error}`;
      yourCode.marks.ShowError($("code-report").textContent, yourCode.file);
      $("code-report").dataset.failed = "yes";
      Status(yourCode.running ? "Your code could not be checked." : "Stopped.");
    } finally {
      runner.End();
      yourCode.running = null;
      $("code-report").dataset.done = "yes";
      Busy(null);
    }
  }

  // The parameters, and their kinds, of every function a figure's recipe may call.
  function Kinds() {
    const kinds = {};
    for (const section of CGFS_CHECK.sections(yourCode.chapter, yourCode.files)) {
      for (const entry of section.entries) kinds[entry.function] ??= entry.parameters;
    }
    return kinds;
  }

  async function Figures() {
    if (!yourCode.figures) {
      const live = $("live");
      yourCode.figures = new FiguresWorker(
        live.dataset.module,
        CGFS_FIGURES_OF[live.dataset.chapter],
      );
      const described = await yourCode.figures.Request({ op: "describe" });
      yourCode.figureIndex = Object.fromEntries(
        described.figures.map((figure, i) => [figure.name, i]),
      );
    }
    return yourCode.figures;
  }

  // What a draw's verdict and the last check of the same code say together, when they
  // seem to disagree: a sentence, or ''.
  function Teaching(passed) {
    const checked = yourCode.lastCheck;
    if (!checked || checked.code !== yourCode.editor.getValue()) {
      return passed
        ? ""
        : "Check your code (Ctrl+Enter) to see which of your functions the difference may come from.";
    }
    if (passed && checked.failed) {
      return (
        "The picture is the same as ours, yet your last check failed cases: the cases try what one picture may " +
        "not show (another canvas size, a point off the canvas, a value the picture rounds away). The report above " +
        "names them."
      );
    }
    if (!passed && !checked.failed) {
      return (
        "Every case passed, yet the picture differs: the cases try your functions one by one; the picture also " +
        "takes the code around them (how they are called, the scene set up) and any function the cases do not cover."
      );
    }
    return "";
  }

  // A ray-traced figure drawn in Python, at a quarter of its resolution, while the full
  // one is drawn.
  function ShowPreview(pixels, width, height) {
    ComparisonView.PutOn($("code-preview"), pixels, width, height);
    $("code-preview").hidden = false;
  }

  // The reader's picture of a figure chosen with the chapter's controls, beside ours in
  // the figure column (chapter.js's Controls), when "draw it with my code too" is ticked.
  function Beside(name, text, pixels = null, width = 0, height = 0) {
    const box = $("controls-yours");
    if (!box || !$("controls-mine").checked || $("code-figure").value !== name) return;
    box.hidden = false;
    box.querySelector("canvas").hidden = pixels === null;
    if (pixels) ComparisonView.PutOn(box.querySelector("canvas"), pixels, width, height);
    box.querySelector("p").textContent = `${name}, ${text}`;
    box.dataset.figure = name;
  }

  function DrawBeside(name) {
    if (!$("controls-mine")?.checked || $("code-panel").dataset.busy) return;
    if (!(name in yourCode.drawings)) {
      // a figure the cases' functions alone do not draw
      $("controls-yours").hidden = false;
      $("controls-yours").querySelector("canvas").hidden = true;
      $("controls-yours").querySelector("p").textContent =
        `${name}: not drawn with your functions here (they draw ` +
        `${Object.keys(yourCode.drawings).join(", ")})`;
      $("controls-yours").dataset.figure = name;
      return;
    }
    $("code-figure").value = name;
    $("controls-yours").hidden = false;
    $("controls-yours").querySelector("p").textContent = `${name}: drawing yours…`;
    Draw();
  }

  // Draw: the chosen figure with the reader's functions, beside ours and their difference,
  // and what cgfs-compare says of it.
  async function Draw() {
    const name = $("code-figure").value;
    const recipe = yourCode.drawings[name];
    const { width, height } = recipe.given.canvas;
    Save();
    Busy("draw");
    $("code-drawing").hidden = true;
    $("code-comparison").textContent = "";
    delete $("code-drawing").dataset.verdict;
    const start = performance.now();
    const drawn = await DrawWithCode({
      language: yourCode.language,
      code: yourCode.editor.getValue(),
      file: yourCode.file,
      functions: Object.keys(Kinds()),
      names: CGFS_CHECK.NAMES,
      recipe,
      kinds: Kinds(),
      seconds: kDrawLimit,
      onStatus: Status,
      onStarting: PythonStarting,
      onPreview: (pixels) => ShowPreview(pixels, width, height),
      onProgress: (fraction) =>
        Status(`drawing ${name} with your functions… ${Math.round(fraction * 100)} %`),
    });
    $("code-preview").hidden = true;
    try {
      if (drawn.cancelled) {
        Status("Stopped.");
        return;
      }
      if (drawn.problem) {
        Status(`${name} could not be drawn with your functions: ${drawn.problem}`);
        Beside(name, `yours could not be drawn: ${drawn.problem}`);
        return;
      }
      const seconds = (performance.now() - start) / 1000;
      Status(`comparing with ours…`);
      const figures = await Figures();
      const index = yourCode.figureIndex[name];
      const ours = await figures.Request({ op: "draw", index, width, height, full: true });
      const compared = await figures.Request({
        op: "compare",
        index,
        width,
        height,
        rgba: drawn.pixels,
      });
      if (ours.problem || compared.problem) {
        Status(`${name} could not be compared: ${ours.problem ?? compared.problem}`);
        return;
      }
      yourCode.comparison.Show({
        ours: ours.pixels,
        yours: drawn.pixels,
        difference: compared.difference,
        width,
        height,
        first: { column: compared.column, row: compared.row },
        colours: compared.colours,
      });
      $("code-teach").textContent = Teaching(compared.passed);
      const notes = compared.passed ? [] : (drawn.notes ?? []);
      $("code-comparison").textContent =
        `${name}, drawn with your functions, compared with ours:\n${compared.text}` +
        notes.map((note) => `${note}\n`).join("");
      $("code-drawing").dataset.verdict = compared.passed ? "pass" : "fail";
      $("code-drawing").hidden = false;
      $("code-drawing").drawn = drawn; // the reader's picture, as drawn (the site's test reads it)
      Beside(
        name,
        `yours: ${compared.passed ? "the same as ours" : "not the same as ours (the Your code tab shows how)"}`,
        drawn.pixels,
        width,
        height,
      );
      Status(
        `${name} drawn with your functions in ${seconds.toFixed(1)} s: ${compared.passed ? "the same as ours" : "not the same as ours"}`,
      );
    } finally {
      Busy(null);
    }
  }

  function CheckAtCursor() {
    const name = FunctionAtCursor();
    if (name) Check(name);
  }

  // The chapter's functions and their verdicts in the last full check, for the index:
  // { language, passed: [names], failed: [names], unwritten: [names] }.
  function KeepProgress(records, language) {
    const own = new Set(yourCode.files[yourCode.chapter].functions.map((entry) => entry.function));
    const rank = ["passed", "unwritten", "failed"]; // a function's verdict: its cases' worst
    const verdicts = new Map();
    for (const { function: name, status } of records) {
      if (!own.has(name)) continue;
      const verdict =
        status === "pass" ? "passed" : status === "not written" ? "unwritten" : "failed";
      if (rank.indexOf(verdict) >= rank.indexOf(verdicts.get(name) ?? "passed"))
        verdicts.set(name, verdict);
    }
    const named = (verdict) =>
      [...verdicts].filter(([, each]) => each === verdict).map(([name]) => name);
    Store(
      ProgressKey(yourCode.chapter),
      JSON.stringify({
        language,
        passed: named("passed"),
        failed: named("failed"),
        unwritten: named("unwritten"),
      }),
    );
  }

  const Base64Url = (bytes) => {
    let text = "";
    for (let i = 0; i < bytes.length; i += 8192)
      text += String.fromCharCode(...bytes.subarray(i, i + 8192));
    return btoa(text).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
  };

  // A link to this page with the code in its fragment (after the #, which a browser sends
  // to no server): deflated, in base64url.
  async function MakeLink() {
    Save();
    const deflated = new Response(
      new Blob([yourCode.editor.getValue()])
        .stream()
        .pipeThrough(new CompressionStream("deflate-raw")),
    );
    const link =
      `${location.href.replace(/#.*$/, "")}#code=${yourCode.language}:` +
      Base64Url(new Uint8Array(await deflated.arrayBuffer()));
    $("code-link").value = link;
    $("code-link").hidden = false;
    $("code-link").select();
    let copied = false;
    try {
      await navigator.clipboard.writeText(link);
      copied = true;
    } catch {
      // no clipboard here (a page opened from a file, or refused): the link is shown to copy
    }
    Status(
      `A link with your code (${link.length} characters)${copied ? ", copied" : ""}: it opens this page with ` +
        "your code in the editor. Nothing is sent anywhere: the code is in the link itself.",
    );
  }

  // The code a link brought, inflated, at most kMostCode bytes; or throws why not.
  async function LinkedCode(text) {
    const bytes = Uint8Array.from(atob(text.replace(/-/g, "+").replace(/_/g, "/")), (c) =>
      c.charCodeAt(0),
    );
    const reader = new Blob([bytes])
      .stream()
      .pipeThrough(new DecompressionStream("deflate-raw"))
      .getReader();
    const parts = [];
    for (let size = 0; ;) {
      const { done, value } = await reader.read();
      if (done) break;
      size += value.length;
      if (size > kMostCode) {
        reader.cancel();
        throw new Error("it holds more than 1 MB of code");
      }
      parts.push(value);
    }
    return new TextDecoder("utf-8", { fatal: true }).decode(await new Blob(parts).arrayBuffer());
  }

  // Opened from a link with code: that code in the editor, over the reader's own (one
  // Ctrl+Z brings theirs back).
  async function OpenLinked() {
    const [, language, text] = kLinked;
    let code;
    try {
      code = await LinkedCode(text);
    } catch (error) {
      Status(
        `This link's code could not be read (${error.message ?? error}): the editor has your own.`,
      );
      return;
    }
    if (language !== yourCode.language) ShowCode(language, OpeningCode(language));
    yourCode.editor.setValue(code);
    Status("The code of the link you opened is in the editor; Ctrl+Z brings back what you had.");
  }

  function Stop() {
    yourCode.running?.End();
    yourCode.running = null;
    DrawWithCode.Cancel();
  }

  function Download() {
    Save();
    const link = document.createElement("a");
    link.href = URL.createObjectURL(new Blob([yourCode.editor.getValue()], { type: "text/plain" }));
    link.download = yourCode.file;
    link.click();
    setTimeout(() => URL.revokeObjectURL(link.href), 1000);
  }

  async function Open(file) {
    const language = /\.py$/i.test(file.name)
      ? "python"
      : /\.(m|c)?js$/i.test(file.name)
        ? "javascript"
        : null;
    if (!language) {
      Status(`${file.name}: open a Python file (.py) or JavaScript (.js, .mjs, .cjs)`);
      return;
    }
    if (file.size > kMostCode) {
      Status(`${file.name}: larger than 1 MB, not a chapter`);
      return;
    }
    Save();
    ShowCode(language, await file.text(), file.name);
    Store(`${StorageKey(yourCode.chapter, language)}:file`, file.name);
    Save();
    Status(`opened ${file.name}`);
  }

  function StartOver() {
    const { chapter, language } = yourCode;
    if (
      !confirm(
        `Start ${chapter}'s ${language === "python" ? "Python" : "JavaScript"} again? What is in the editor is lost ` +
          "(Download keeps a copy).",
      )
    )
      return;
    Store(StorageKey(chapter, language), null);
    Store(`${StorageKey(chapter, language)}:file`, null);
    ShowCode(language, OpeningCode(language));
    Status("started again");
  }

  function ChooseLanguage(language) {
    Save();
    Store("cgfs-code:language", language);
    ShowCode(language, OpeningCode(language));
    Status("");
    WarmPython();
  }

  // Python started as soon as it is the language, while the reader reads and types.
  function WarmPython() {
    if (yourCode.language !== "python") return;
    SupplyFor("python").Warm(PythonStarting);
  }

  function ListDrawings() {
    const names = Object.keys(yourCode.drawings);
    for (const name of names) $("code-figure").append(new Option(name, name));
    $("code-draw-group").hidden = names.length === 0;
    $("code-no-drawing").hidden = names.length > 0;
  }

  function StartYourCode() {
    yourCode.editor = CodeMirror.fromTextArea($("code-editor"), {
      lineNumbers: true,
      indentUnit: 2,
      tabSize: 8,
      indentWithTabs: false,
      viewportMargin: 20,
      gutters: ["code-marks", "CodeMirror-linenumbers"],
      extraKeys: {
        Tab: (editor) =>
          editor.execCommand(editor.somethingSelected() ? "indentMore" : "insertSoftTab"),
        "Ctrl-Enter": () => Check(),
        "Cmd-Enter": () => Check(),
        "Shift-Ctrl-Enter": CheckAtCursor,
        "Shift-Cmd-Enter": CheckAtCursor,
      },
    });
    yourCode.marks = new EditorMarks(yourCode.editor, ShowInReport);
    yourCode.editor.on("cursorActivity", ShowFunctionAtCursor);
    let saving = null;
    let checking = null;
    yourCode.editor.on("change", () => {
      clearTimeout(saving);
      saving = setTimeout(Save, 500);
      // "check as I type" (JavaScript, whose worker starts at once): a check after a pause.
      clearTimeout(checking);
      if ($("code-auto").checked && yourCode.language === "javascript")
        checking = setTimeout(() => Check(), kTypingPause);
    });
    const language = Stored("cgfs-code:language") === "python" ? "python" : "javascript";
    ShowCode(language, OpeningCode(language));
    ListDrawings();
    $("code-language").addEventListener("change", (event) => ChooseLanguage(event.target.value));
    $("code-check").addEventListener("click", () => Check());
    $("code-check-one").addEventListener("click", CheckAtCursor);
    ShowFunctionAtCursor();
    $("code-draw").addEventListener("click", Draw);
    $("code-stop").addEventListener("click", Stop);
    $("code-download").addEventListener("click", Download);
    $("code-link-button").addEventListener("click", MakeLink);
    $("code-open-button").addEventListener("click", () => $("code-open").click());
    $("code-open").addEventListener("change", (event) => {
      if (event.target.files[0]) Open(event.target.files[0]);
      event.target.value = "";
    });
    $("code-start-over").addEventListener("click", StartOver);
    document.addEventListener("cgfs-figure", ({ detail }) => DrawBeside(detail));
    $("controls-mine")?.addEventListener("change", (event) => {
      if (!event.target.checked) $("controls-yours").hidden = true;
      else DrawBeside(document.querySelector('#controls input[type="radio"]:checked')?.value);
    });
    window.addEventListener("beforeunload", Save);
    // CodeMirror measures itself when shown: the panel starts hidden behind its tab.
    document.addEventListener("cgfs-tab", ({ detail }) => {
      if (detail !== "tab-code") return;
      yourCode.editor.refresh();
      WarmPython();
    });
    yourCode.comparison = new ComparisonView();
    if ($("tab-code").getAttribute("aria-selected") === "true") WarmPython(); // (its tab chosen before this ran)
    if (kLinked) {
      OpenLinked().finally(() => {
        $("code-panel").dataset.ready = "yes";
      });
    } else {
      $("code-panel").dataset.ready = "yes";
    }
  }

  StartYourCode();
})();
