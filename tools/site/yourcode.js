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
  const storageKey = (chapter, language) => `cgfs-code:${chapter}:${language}`;
  // Which functions of the chapter passed the last full check: read by the index (index.js).
  const progressKey = (chapter) => `cgfs-progress:${chapter}`;
  const kTypingPause = 1000; // milliseconds without typing before "check as I type" checks
  const kMostCode = 1 << 20; // bytes of code a file or a link may bring (a chapter is a few KB)
  // A link's code (#code=LANGUAGE:DEFLATED-BASE64URL), read before chapter.js rewrites the
  // address for the figure shown.
  const kLinked = /^#code=(javascript|python):([A-Za-z0-9_-]+)$/.exec(location.hash);

  function readStored(key) {
    try {
      return localStorage.getItem(key);
    } catch {
      return null; // storage refused (a private window, a page opened from a file): nothing kept
    }
  }

  function store(key, value) {
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
  function openingCode(language) {
    const { chapter, files, title } = yourCode;
    const stored = readStored(storageKey(chapter, language));
    if (stored !== null) return stored;
    const previous = CGFS_CHECK.previousChapter(chapter, files);
    const before = previous && readStored(storageKey(previous, language));
    return before
      ? CGFS_CHECK.carriedForward(chapter, before, files, language, title)
      : CGFS_CHECK.freshStarter(chapter, files, language, title);
  }

  function showCode(language, code, file) {
    yourCode.language = language;
    yourCode.file =
      file ??
      readStored(`${storageKey(yourCode.chapter, language)}:file`) ??
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

  function save() {
    store(storageKey(yourCode.chapter, yourCode.language), yourCode.editor.getValue());
  }

  function setBusy(what) {
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
      showFunctionAtCursor(); // enabled only in one of the chapter's functions
      refillWorkers();
    }
  }

  function setStatus(text) {
    $("code-status").textContent = text;
  }

  // How far Python's start has come (0 to 1), on its bar; the bar gone once it has started.
  function pythonStarting(fraction) {
    $("code-python-start").hidden = fraction >= 1;
    $("code-python-start").value = fraction;
    if (fraction < 1) setStatus(`starting Python (Pyodide)… ${Math.round(fraction * 100)} %`);
    else if ($("code-status").textContent.startsWith("starting Python"))
      setStatus("Python is ready.");
  }

  // The report, a line to a span: a function's first line names it (data-function), for
  // the editor's marks to show.
  function showReport(lines) {
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
  function showInReport(name) {
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
  function functionAtCursor() {
    const names = CGFS_CHECK.functionsOf(CGFS_CHECK.sections(yourCode.chapter, yourCode.files));
    return yourCode.marks.functionAtCursor(names, yourCode.language);
  }

  function showFunctionAtCursor() {
    const name = functionAtCursor();
    $("code-check-one").textContent = name ? `Check ${name}` : "Check one function";
    $("code-check-one").title = name
      ? `${name}'s cases alone (Shift+Ctrl+Enter), as --function ${name} does`
      : "Put the cursor in one of the chapter's functions to check it alone";
    $("code-check-one").dataset.function = name ?? "";
    if (!$("code-panel").dataset.busy) $("code-check-one").disabled = !name;
  }

  // Check: the chapter's cases, and those of the chapters it keeps, on the reader's code;
  // only: one function's cases alone (as --function NAME).
  async function runCheck(only = null) {
    const { chapter, files, language } = yourCode;
    if (yourCode.running || $("code-panel").dataset.busy) return;
    save();
    setBusy("check");
    $("code-report").textContent = "";
    $("code-report").dataset.failed = "";
    yourCode.marks.clear();
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
      onStatus: setStatus,
      onStarting: pythonStarting,
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
      showReport(lines);
      yourCode.marks.showChecked(records, language);
      $("code-report").dataset.failed = failed ? "yes" : "no";
      const checked = (Date.now() - runner.started) / 1000;
      if (runner.ended && yourCode.running !== runner) {
        setStatus(`Stopped after ${checked.toFixed(1)} s: the cases not run are not checked.`);
        return;
      }
      if (only === null) {
        yourCode.lastCheck = { code: runner.code, failed };
        keepProgress(records, language);
      }
      setStatus(
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
      yourCode.marks.showError($("code-report").textContent, yourCode.file);
      $("code-report").dataset.failed = "yes";
      setStatus(yourCode.running ? "Your code could not be checked." : "Stopped.");
    } finally {
      runner.end();
      yourCode.running = null;
      $("code-report").dataset.done = "yes";
      setBusy(null);
    }
  }

  // The case files' entry of every function a figure's recipe may call.
  function functionEntries() {
    const entries = {};
    for (const section of CGFS_CHECK.sections(yourCode.chapter, yourCode.files)) {
      for (const entry of section.entries) entries[entry.function] ??= entry;
    }
    return entries;
  }

  async function ourFigures() {
    if (!yourCode.figures) {
      const live = $("live");
      yourCode.figures = new FiguresWorker(
        live.dataset.module,
        CGFS_FIGURES_OF[live.dataset.chapter],
      );
      const described = await yourCode.figures.request({ op: "describe" });
      yourCode.figureIndex = Object.fromEntries(
        described.figures.map((figure, i) => [figure.name, i]),
      );
    }
    return yourCode.figures;
  }

  // What a draw's verdict and the last check of the same code say together, when they
  // seem to disagree: a sentence, or ''.
  function teaching(passed) {
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
  function showPreview(pixels, width, height) {
    ComparisonView.putOn($("code-preview"), pixels, width, height);
    $("code-preview").hidden = false;
  }

  // The reader's picture of a figure chosen with the chapter's controls, beside ours in
  // the figure column (chapter.js's setUpControls), when "draw it with my code too" is ticked.
  function beside(name, text, pixels = null, width = 0, height = 0) {
    const box = $("controls-yours");
    if (!box || !$("controls-mine").checked || $("code-figure").value !== name) return;
    box.hidden = false;
    box.querySelector("canvas").hidden = pixels === null;
    if (pixels) ComparisonView.putOn(box.querySelector("canvas"), pixels, width, height);
    box.querySelector("p").textContent = `${name}, ${text}`;
    box.dataset.figure = name;
  }

  function drawBeside(name) {
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
    draw();
  }

  // Draw: the chosen figure with the reader's functions, beside ours and their difference,
  // and what cgfs-compare says of it.
  async function draw() {
    const name = $("code-figure").value;
    const recipe = yourCode.drawings[name];
    const { width, height } = recipe.given.canvas;
    save();
    setBusy("draw");
    $("code-drawing").hidden = true;
    $("code-comparison").textContent = "";
    delete $("code-drawing").dataset.verdict;
    const start = performance.now();
    const drawn = await drawWithCode({
      language: yourCode.language,
      code: yourCode.editor.getValue(),
      file: yourCode.file,
      names: CGFS_CHECK.NAMES,
      recipe,
      entries: functionEntries(),
      seconds: kDrawLimit,
      onStatus: setStatus,
      onStarting: pythonStarting,
      onPreview: (pixels) => showPreview(pixels, width, height),
      onProgress: (fraction) =>
        setStatus(`drawing ${name} with your functions… ${Math.round(fraction * 100)} %`),
    });
    $("code-preview").hidden = true;
    try {
      if (drawn.cancelled) {
        setStatus("Stopped.");
        return;
      }
      if (drawn.problem) {
        setStatus(`${name} could not be drawn with your functions: ${drawn.problem}`);
        beside(name, `yours could not be drawn: ${drawn.problem}`);
        return;
      }
      const seconds = (performance.now() - start) / 1000;
      setStatus(`comparing with ours…`);
      const figures = await ourFigures();
      const index = yourCode.figureIndex[name];
      const ours = await figures.request({ op: "draw", index, width, height, full: true });
      const compared = await figures.request({
        op: "compare",
        index,
        width,
        height,
        rgba: drawn.pixels,
      });
      if (ours.problem || compared.problem) {
        setStatus(`${name} could not be compared: ${ours.problem ?? compared.problem}`);
        return;
      }
      yourCode.comparison.show({
        ours: ours.pixels,
        yours: drawn.pixels,
        difference: compared.difference,
        width,
        height,
        first: { column: compared.column, row: compared.row },
        colours: compared.colours,
      });
      $("code-teach").textContent = teaching(compared.passed);
      const notes = compared.passed ? [] : (drawn.notes ?? []);
      $("code-comparison").textContent =
        `${name}, drawn with your functions, compared with ours:\n${compared.text}` +
        notes.map((note) => `${note}\n`).join("");
      $("code-drawing").dataset.verdict = compared.passed ? "pass" : "fail";
      $("code-drawing").hidden = false;
      $("code-drawing").drawn = drawn; // the reader's picture, as drawn (the site's test reads it)
      beside(
        name,
        `yours: ${compared.passed ? "the same as ours" : "not the same as ours (the Your code tab shows how)"}`,
        drawn.pixels,
        width,
        height,
      );
      setStatus(
        `${name} drawn with your functions in ${seconds.toFixed(1)} s: ${compared.passed ? "the same as ours" : "not the same as ours"}`,
      );
    } finally {
      setBusy(null);
    }
  }

  function checkAtCursor() {
    const name = functionAtCursor();
    if (name) runCheck(name);
  }

  // The chapter's functions and their verdicts in the last full check, for the index:
  // { language, passed: [names], failed: [names], unwritten: [names] }.
  function keepProgress(records, language) {
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
    store(
      progressKey(yourCode.chapter),
      JSON.stringify({
        language,
        passed: named("passed"),
        failed: named("failed"),
        unwritten: named("unwritten"),
      }),
    );
  }

  const base64Url = (bytes) => {
    let text = "";
    for (let i = 0; i < bytes.length; i += 8192)
      text += String.fromCharCode(...bytes.subarray(i, i + 8192));
    return btoa(text).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
  };

  // A link to this page with the code in its fragment (after the #, which a browser sends
  // to no server): deflated, in base64url.
  async function makeLink() {
    save();
    const deflated = new Response(
      new Blob([yourCode.editor.getValue()])
        .stream()
        .pipeThrough(new CompressionStream("deflate-raw")),
    );
    const link =
      `${location.href.replace(/#.*$/, "")}#code=${yourCode.language}:` +
      base64Url(new Uint8Array(await deflated.arrayBuffer()));
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
    setStatus(
      `A link with your code (${link.length} characters)${copied ? ", copied" : ""}: it opens this page with ` +
        "your code in the editor. Nothing is sent anywhere: the code is in the link itself.",
    );
  }

  // The code a link brought, inflated, at most kMostCode bytes; or throws why not.
  async function linkedCode(text) {
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
  async function openLinked() {
    const [, language, text] = kLinked;
    let code;
    try {
      code = await linkedCode(text);
    } catch (error) {
      setStatus(
        `This link's code could not be read (${error.message ?? error}): the editor has your own.`,
      );
      return;
    }
    if (language !== yourCode.language) showCode(language, openingCode(language));
    yourCode.editor.setValue(code);
    setStatus("The code of the link you opened is in the editor; Ctrl+Z brings back what you had.");
  }

  function stopRun() {
    yourCode.running?.end();
    yourCode.running = null;
    drawWithCode.Cancel();
  }

  function downloadCode() {
    save();
    const link = document.createElement("a");
    link.href = URL.createObjectURL(new Blob([yourCode.editor.getValue()], { type: "text/plain" }));
    link.download = yourCode.file;
    link.click();
    setTimeout(() => URL.revokeObjectURL(link.href), 1000);
  }

  async function openFile(file) {
    const language = /\.py$/i.test(file.name)
      ? "python"
      : /\.(m|c)?js$/i.test(file.name)
        ? "javascript"
        : null;
    if (!language) {
      setStatus(`${file.name}: open a Python file (.py) or JavaScript (.js, .mjs, .cjs)`);
      return;
    }
    if (file.size > kMostCode) {
      setStatus(`${file.name}: larger than 1 MB, not a chapter`);
      return;
    }
    save();
    showCode(language, await file.text(), file.name);
    store(`${storageKey(yourCode.chapter, language)}:file`, file.name);
    save();
    setStatus(`opened ${file.name}`);
  }

  function startOver() {
    const { chapter, language } = yourCode;
    if (
      !confirm(
        `Start ${chapter}'s ${language === "python" ? "Python" : "JavaScript"} again? What is in the editor is lost ` +
          "(Download keeps a copy).",
      )
    )
      return;
    store(storageKey(chapter, language), null);
    store(`${storageKey(chapter, language)}:file`, null);
    showCode(language, openingCode(language));
    setStatus("started again");
  }

  function chooseLanguage(language) {
    save();
    store("cgfs-code:language", language);
    showCode(language, openingCode(language));
    setStatus("");
    warmPython();
  }

  // Python started as soon as it is the language, while the reader reads and types.
  function warmPython() {
    if (yourCode.language !== "python") return;
    supplyFor("python").warm(pythonStarting);
  }

  function listDrawings() {
    const names = Object.keys(yourCode.drawings);
    for (const name of names) $("code-figure").append(new Option(name, name));
    $("code-draw-group").hidden = names.length === 0;
    $("code-no-drawing").hidden = names.length > 0;
  }

  function startYourCode() {
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
        "Ctrl-Enter": () => runCheck(),
        "Cmd-Enter": () => runCheck(),
        "Shift-Ctrl-Enter": checkAtCursor,
        "Shift-Cmd-Enter": checkAtCursor,
      },
    });
    yourCode.marks = new EditorMarks(yourCode.editor, showInReport);
    yourCode.editor.on("cursorActivity", showFunctionAtCursor);
    let saving = null;
    let checking = null;
    yourCode.editor.on("change", () => {
      clearTimeout(saving);
      saving = setTimeout(save, 500);
      // "check as I type" (JavaScript, whose worker starts at once): a check after a pause.
      clearTimeout(checking);
      if ($("code-auto").checked && yourCode.language === "javascript")
        checking = setTimeout(() => runCheck(), kTypingPause);
    });
    const language = readStored("cgfs-code:language") === "python" ? "python" : "javascript";
    showCode(language, openingCode(language));
    listDrawings();
    $("code-language").addEventListener("change", (event) => chooseLanguage(event.target.value));
    $("code-check").addEventListener("click", () => runCheck());
    $("code-check-one").addEventListener("click", checkAtCursor);
    showFunctionAtCursor();
    $("code-draw").addEventListener("click", draw);
    $("code-stop").addEventListener("click", stopRun);
    $("code-download").addEventListener("click", downloadCode);
    $("code-link-button").addEventListener("click", makeLink);
    $("code-open-button").addEventListener("click", () => $("code-open").click());
    $("code-open").addEventListener("change", (event) => {
      if (event.target.files[0]) openFile(event.target.files[0]);
      event.target.value = "";
    });
    $("code-start-over").addEventListener("click", startOver);
    document.addEventListener("cgfs-figure", ({ detail }) => drawBeside(detail));
    $("controls-mine")?.addEventListener("change", (event) => {
      if (!event.target.checked) $("controls-yours").hidden = true;
      else drawBeside(document.querySelector('#controls input[type="radio"]:checked')?.value);
    });
    window.addEventListener("beforeunload", save);
    // CodeMirror measures itself when shown: the panel starts hidden behind its tab.
    document.addEventListener("cgfs-tab", ({ detail }) => {
      if (detail !== "tab-code") return;
      yourCode.editor.refresh();
      warmPython();
    });
    yourCode.comparison = new ComparisonView();
    if ($("tab-code").getAttribute("aria-selected") === "true") warmPython(); // (its tab chosen before this ran)
    if (kLinked) {
      openLinked().finally(() => {
        $("code-panel").dataset.ready = "yes";
      });
    } else {
      $("code-panel").dataset.ready = "yes";
    }
  }

  startYourCode();
})();
