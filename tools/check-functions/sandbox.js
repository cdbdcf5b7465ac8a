// The sandbox a student's code runs in while the checker judges it: Debian's bubblewrap
// (bwrap) with the student's folder read-only (their code imports its own files), a
// private empty /tmp, no network, the system's programs and libraries read-only, the
// interpreter's own files (its program, its libraries, its standard library, a virtual
// environment's packages) and nothing else of the file system: not the repository's case
// files, not the checker, nor any copy of the case files found in a folder bound in. Every
// path is resolved to its real path before it is compared, hidden or bound. Its own PID
// namespace (it can neither signal the checker nor outlive it: it ends with it), its own
// session (it cannot write to the checker's terminal), an environment of four names, no
// word of the checker's command line (bwrap reads its arguments from a pipe), and capped
// memory, CPU time and number of processes. Where bwrap cannot run, `why()` says why, in
// words for the report's first line, and the code runs as the user.
"use strict";

const { execFileSync, spawnSync } = require("child_process");
const fs = require("fs");
const path = require("path");

const REPO = fs.realpathSync(path.resolve(__dirname, "..", ".."));
const CASES = path.join(REPO, "tests", "cases");
const RUNNERS = path.join(__dirname, "runners");
const MEMORY = 3 << 30;  // bytes of data a process may have (RLIMIT_DATA): a memory bomb ends in seconds
const PROCESSES = 256;  // processes the sandbox may add to the user's
const SCAN_LIMIT = 200000;  // entries of the bound folders searched for copies of the case files
const SYSTEM = ["/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"];

let checked = null;

// null when bwrap runs here, else why not.
function why() {
  if (process.env.CGFS_NO_SANDBOX === "1") return "CGFS_NO_SANDBOX=1 turned it off";
  if (checked !== null) return checked || null;
  const probe = spawnSync("bwrap", ["--ro-bind", "/", "/", "--unshare-all", "--die-with-parent", "--new-session", "true"],
    { stdio: "ignore", timeout: 10000 });
  if (probe.error?.code === "ENOENT") checked = "bubblewrap is not installed (Debian: sudo apt install bubblewrap)";
  else if (probe.status !== 0) checked = "bwrap cannot make a sandbox here (are user namespaces turned off?)";
  else checked = "";
  return checked || null;
}

const real = (file) => {
  try {
    return fs.realpathSync(file);
  } catch {
    return null;
  }
};
const inside = (child, parent) => child === parent || child.startsWith(parent === "/" ? "/" : parent + path.sep);
const system = (file) => SYSTEM.some((dir) => inside(file, dir));

// The shared libraries a program loads from outside the system's folders (pyenv's
// libpython), as ldd finds them.
function ownLibraries(program) {
  try {
    const text = execFileSync("ldd", [program], { encoding: "utf8", timeout: 10000, stdio: ["ignore", "pipe", "ignore"] });
    return [...text.matchAll(/=> (\/\S+)/g)].map((match) => match[1]).filter((file) => !system(real(file) ?? file));
  } catch {
    return [];
  }
}

let python = null;

// The python3 the user's PATH names, as the program it is (not a launcher such as
// pyenv's, which the sandbox could not run), and the files it needs: its program, its
// libraries, the folders of its import path (standard library, site-packages) and a
// virtual environment's pyvenv.cfg; never the folder above them. null when there is none.
function pythonInterpreter() {
  if (python === null) {
    try {
      const script = "import json, sys; print(json.dumps([sys.executable, sys.prefix, sys.base_prefix, [p for p in sys.path if p]]))";
      const text = execFileSync("python3", ["-c", script],
        { encoding: "utf8", timeout: 10000, stdio: ["ignore", "pipe", "ignore"], cwd: "/" });
      const [executable, prefix, basePrefix, importPath] = JSON.parse(text);
      const files = [executable, real(executable), path.join(prefix, "pyvenv.cfg"), ...importPath,
        ...ownLibraries(real(executable) ?? executable)].filter((file) => file && fs.existsSync(file));
      // Searched for copies of the case files: the folders of the import path that are
      // not the installation's own (a virtual environment's packages, the user's,
      // PYTHONPATH's).
      const base = real(basePrefix) ?? basePrefix;
      const searched = importPath.map(real).filter((dir) => dir && !inside(dir, base) && fs.statSync(dir).isDirectory());
      python = { executable, files, searched };
    } catch {
      python = false;
    }
  }
  return python || null;
}

// The files of the interpreter the sandbox needs besides the system's: a Python of pyenv
// or a virtual environment; a Node.js outside /usr (its program and libraries), with the
// folders its modules are found in (NODE_PATH).
function interpreterFiles(language, modulePaths) {
  if (language === "python") return pythonInterpreter()?.files ?? [];
  return [process.execPath, ...ownLibraries(process.execPath), ...modulePaths];
}

// The interpreter's folders searched for copies of the case files: those not of its
// installation (the installation's own, tens of thousands of files, are not searched;
// the repository is hidden from them all the same).
function interpreterSearched(language, modulePaths) {
  const searched = language === "python" ? pythonInterpreter()?.searched ?? [] : modulePaths.map(real);
  return searched.filter((dir) => dir && !system(dir));
}

// Every copy of the case files in the folders bound in, found by a walk of at most
// SCAN_LIMIT entries: a folder that holds the repository or another copy of it (a
// tests/cases folder), a git repository (an older clone's history), a file named as a
// case file or with a case file's bytes. The folders and files to hide, and whether the
// walk was cut short.
function caseFileCopies(folders) {
  const names = new Set(fs.readdirSync(CASES));
  const bySize = new Map();
  for (const name of names) {
    const bytes = fs.readFileSync(path.join(CASES, name));
    bySize.set(bytes.length, [...(bySize.get(bytes.length) ?? []), bytes]);
  }
  const sameBytes = (file) => {
    const candidates = bySize.get(sizeOf(file));
    if (!candidates) return false;
    try {
      const bytes = fs.readFileSync(file);
      return candidates.some((each) => each.equals(bytes));
    } catch {
      return false;
    }
  };
  const hidden = { folders: new Set(), files: new Set(), cut: false };
  let seen = 0;
  const walk = (dir) => {
    let entries;
    try {
      entries = fs.readdirSync(dir, { withFileTypes: true });
    } catch {
      return;
    }
    const here = new Set(entries.map((entry) => entry.name));
    const copy = (here.has("tests") && fs.existsSync(path.join(dir, "tests", "cases"))) ||
      (here.has("HEAD") && here.has("objects") && here.has("refs"));
    if (copy && !folders.includes(dir)) {
      hidden.folders.add(dir);
      return;
    }
    for (const entry of entries) {
      if (++seen > SCAN_LIMIT) {
        hidden.cut = true;
        return;
      }
      const file = path.join(dir, entry.name);
      if (entry.isDirectory()) {
        if (entry.name === ".git" || (entry.name === "cases" && path.basename(dir) === "tests")) hidden.folders.add(file);
        else walk(file);
      } else if (entry.isFile()) {
        if (names.has(entry.name) || sameBytes(file)) hidden.files.add(file);
      }
      if (hidden.cut) return;
    }
  };
  for (const folder of folders) walk(folder);
  return hidden;
}

function sizeOf(file) {
  try {
    return fs.statSync(file).size;
  } catch {
    return -1;
  }
}

// The mounts that hide, from the folders bound in, the repository (all of its folders:
// its tests, its tools, its history), and every copy of the case files in the folders
// `searched`.
function hidingMounts(folders, searched) {
  const args = [];
  if (folders.some((folder) => inside(REPO, folder))) {
    for (const entry of fs.readdirSync(REPO, { withFileTypes: true })) {
      if (entry.isDirectory()) args.push("--tmpfs", path.join(REPO, entry.name));
    }
  }
  const copies = caseFileCopies(searched);
  for (const folder of copies.folders) {
    if (folder !== REPO) args.push("--tmpfs", folder);
  }
  for (const file of copies.files) args.push("--ro-bind", "/dev/null", file);
  if (folders.some((folder) => inside(CASES, folder) || inside(folder, CASES))) args.push("--tmpfs", CASES);
  return { args, cut: copies.cut };
}

function systemMounts() {
  const args = ["--ro-bind", "/usr", "/usr"];
  for (const dir of SYSTEM.slice(1)) {
    let stat;
    try {
      stat = fs.lstatSync(dir);
    } catch {
      continue;
    }
    if (stat.isSymbolicLink()) args.push("--symlink", fs.readlinkSync(dir), dir);
    else if (stat.isDirectory()) args.push("--ro-bind", dir, dir);
  }
  for (const file of ["/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/alternatives", "/etc/localtime"]) {
    if (fs.existsSync(file)) args.push("--ro-bind", file, file);
  }
  return args;
}

// How many processes this user has now: the sandbox may add PROCESSES more (the limit
// counts all of the user's).
function userProcesses() {
  try {
    const uid = process.getuid();
    return fs.readdirSync("/proc").filter((name) => /^\d+$/.test(name)).filter((name) => {
      try {
        return fs.statSync(`/proc/${name}`).uid === uid;
      } catch {
        return false;
      }
    }).length;
  } catch {
    return 1000;
  }
}

// A program by its full path, found on the PATH (the sandbox's programs start with an
// empty environment).
function located(program) {
  for (const dir of (process.env.PATH ?? "/usr/bin:/bin").split(path.delimiter)) {
    const file = path.join(dir, program);
    try {
      fs.accessSync(file, fs.constants.X_OK);
      return file;
    } catch {
      // the next one
    }
  }
  return program;
}

// The command that runs `command` ({ file, args, env }) in the sandbox, with `folders`
// (the student's, real paths) read-only and the working directory the first of them; the
// interpreter's files and the folders its modules come from (`modulePaths`) read-only;
// the limits on the whole run, `seconds` of CPU time. bwrap's own arguments go through
// a pipe (`argsText`, for file descriptor 5), so that /proc shows none of them (only the
// runner's command, which bwrap must see on its own command line); its environment is
// empty. `cut`: the search for copies of the case files stopped at its bound.
function sandboxed(command, { language, folders, seconds, modulePaths = [] }) {
  const own = [...new Set(interpreterFiles(language, modulePaths))].filter((file) => real(file) && !system(real(file)));
  const bound = [...new Set([...folders, ...own.map(real)])];
  const hiding = hidingMounts(bound.filter((file) => fs.statSync(file).isDirectory()),
    [...new Set([...folders, ...interpreterSearched(language, modulePaths)])]);
  const env = Object.entries({ PATH: "/usr/local/bin:/usr/bin:/bin", HOME: "/tmp", LANG: "C.UTF-8", ...command.env })
    .flatMap(([name, value]) => ["--setenv", name, value]);
  const bwrap = [
    "--unshare-all", "--die-with-parent", "--new-session", "--clearenv", ...env,
    ...systemMounts(), "--proc", "/proc", "--dev", "/dev", "--tmpfs", "/tmp",
    ...own.flatMap((file) => ["--ro-bind", file, file]),
    ...folders.flatMap((dir) => ["--ro-bind", dir, dir]),
    ...hiding.args,
    "--ro-bind", RUNNERS, RUNNERS,
    "--chdir", folders[0],
  ];
  const limits = [`--data=${MEMORY}`, `--cpu=${Math.ceil(seconds)}`, `--nproc=${userProcesses() + PROCESSES}`];
  return {
    file: located("prlimit"), args: [...limits, "--", located("bwrap"), "--args", "5", command.file, ...command.args], env: {},
    argsText: bwrap.map((word) => `${word}\0`).join(""), cut: hiding.cut,
  };
}

module.exports = { why, sandboxed, pythonInterpreter, real };
