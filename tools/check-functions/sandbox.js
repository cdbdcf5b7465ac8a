// The sandbox a student's code runs in while the checker judges it: Debian's bubblewrap
// (bwrap) with the student's folder read-only (their code imports its own files), a
// private empty /tmp, no network, the system's programs and libraries read-only, the
// interpreter's own files (its program, its libraries, its standard library, a virtual
// environment's packages) and nothing else of the file system: not the repository's case
// files, not the checker, nor any copy of the case files found in a folder bound in. Every
// path is resolved to its real path before it is compared, hidden or bound. Its own PID
// namespace (it can neither signal the checker nor outlive it: it ends with it), its own
// session (it cannot write to the checker's terminal), an environment of four names, no
// word of the checker's command line (bwrap reads its arguments from a pipe). Bounded as
// a whole: its memory (files in its /tmp included) and its processes and threads together
// in a cgroup of its own where the system lets the checker make one (cgroup v1's memory
// and pids controllers, or v2's), each process alone otherwise (prlimit, said in a note);
// only its /tmp and /dev/shm writable, each a tmpfs of a stated size; no file larger than
// FILE_BYTES; CPU time. Run as root, the code runs as nobody without capabilities (in a
// user namespace; and as nobody outside too where there is no cgroup, since the kernel
// does not count root's processes). Where bwrap cannot run, `why()` says why, in words for
// the report's first line, and the code runs as the user.
"use strict";

const { execFileSync, spawnSync } = require("child_process");
const fs = require("fs");
const path = require("path");

const REPO = fs.realpathSync(path.resolve(__dirname, "..", ".."));
const CASES = path.join(REPO, "tests", "cases");
const RUNNERS = path.join(__dirname, "runners");
const MEMORY = 3 * 2 ** 30; // bytes the sandbox may hold (its cgroup; else each process's RLIMIT_DATA): a memory bomb ends in seconds
const PROCESSES = 256; // processes the sandbox may add to the user's, where there is no cgroup
const TASKS = 128; // processes and threads of the sandbox together, in its cgroup (Node starts about 12)
const TMP_BYTES = 64 << 20; // the private /tmp (the Python runner keeps each case's printing there)
const SHM_BYTES = 16 << 20; // the private /dev/shm
const FILE_BYTES = 64 << 20; // the largest file the code may write (RLIMIT_FSIZE)
const NOBODY = "65534"; // run as root, the code runs as this user and group (Debian's nobody)
const isRoot = () => process.getuid?.() === 0;
const SCAN_LIMIT = 200000; // entries of the bound folders searched for copies of the case files
const SYSTEM = ["/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"];

let checked = null;

// null when bwrap runs here, else why not.
function why() {
  if (process.env.CGFS_NO_SANDBOX === "1") return "CGFS_NO_SANDBOX=1 turned it off";
  if (checked !== null) return checked || null;
  const probe = spawnSync(
    "bwrap",
    ["--ro-bind", "/", "/", "--unshare-all", "--die-with-parent", "--new-session", "true"],
    { stdio: "ignore", timeout: 10000 },
  );
  if (probe.error?.code === "ENOENT")
    checked = "bubblewrap is not installed (Debian: sudo apt install bubblewrap)";
  else if (probe.status !== 0)
    checked = "bwrap cannot make a sandbox here (are user namespaces turned off?)";
  else checked = "";
  return checked || null;
}

// The cgroup the sandbox runs in: { folders, procs, note }, made once a run in the
// checker's own cgroup (v1: one folder in each of the memory and pids hierarchies; v2:
// one folder with both controllers), with the sandbox's memory and tasks capped; or
// { folders: [], note } when none can be made here (a cgroup file system read-only, as
// in most containers; v2 without the controllers delegated), `note` saying so.
let cgroup = null;

function writeTo(file, text) {
  fs.writeFileSync(file, text);
}

function makeCgroup() {
  if (process.env.CGFS_NO_CGROUP === "1")
    return {
      folders: [],
      note: "CGFS_NO_CGROUP=1: the sandbox's memory and processes are capped for each process, not together",
    };
  const name = `cgfs-check-${process.pid}`;
  const lines = fs
    .readFileSync("/proc/self/cgroup", "utf8")
    .trim()
    .split("\n")
    .map((line) => line.split(":"));
  const v1 = (controller) => lines.find(([, list]) => list.split(",").includes(controller))?.[2];
  const made = [];
  try {
    if (v1("memory") !== undefined && v1("pids") !== undefined) {
      for (const [controller, file, value] of [
        ["memory", "memory.limit_in_bytes", MEMORY],
        ["pids", "pids.max", TASKS],
      ]) {
        const folder = path.join("/sys/fs/cgroup", controller, v1(controller), name);
        fs.mkdirSync(folder);
        made.push(folder);
        writeTo(path.join(folder, file), `${value}`);
      }
      try {
        // no swap beyond the cap, where the kernel accounts for swap
        writeTo(path.join(made[0], "memory.memsw.limit_in_bytes"), `${MEMORY}`);
      } catch {
        // no swap accounting: the memory cap holds all the same
      }
    } else {
      const own = lines.find(([id]) => id === "0")?.[2];
      if (own === undefined) throw new Error("no cgroup v2");
      const folder = path.join("/sys/fs/cgroup", own, name);
      fs.mkdirSync(folder);
      made.push(folder);
      const controllers = fs
        .readFileSync(path.join(folder, "cgroup.controllers"), "utf8")
        .split(/\s+/);
      if (!controllers.includes("memory") || !controllers.includes("pids"))
        throw new Error("controllers not delegated");
      writeTo(path.join(folder, "memory.max"), `${MEMORY}`);
      writeTo(path.join(folder, "pids.max"), `${TASKS}`);
      try {
        writeTo(path.join(folder, "memory.swap.max"), "0");
      } catch {
        // no swap accounting: the memory cap holds all the same
      }
    }
    return { folders: made, note: null };
  } catch {
    for (const folder of made.reverse()) {
      try {
        fs.rmdirSync(folder);
      } catch {
        // left for the system
      }
    }
    return {
      folders: [],
      note: "no cgroup can be made here: the sandbox's memory and processes are capped for each process, not together",
    };
  }
}

function sandboxCgroup() {
  cgroup ??= makeCgroup();
  return cgroup;
}

// The PIDs in the sandbox's cgroup now (none where there is no cgroup).
function cgroupProcesses() {
  const pids = new Set();
  for (const folder of cgroup?.folders ?? []) {
    try {
      for (const pid of fs.readFileSync(path.join(folder, "cgroup.procs"), "utf8").split(/\s+/))
        if (pid) pids.add(Number(pid));
    } catch {
      // gone
    }
  }
  return [...pids];
}

// Ends every process in the sandbox's cgroup, waits until there is none (at most 10 s),
// and removes the cgroup.
async function removeCgroup() {
  if (!cgroup) return;
  const deadline = Date.now() + 10000;
  for (;;) {
    const pids = cgroupProcesses();
    if (pids.length === 0 || Date.now() > deadline) break;
    for (const pid of pids) {
      try {
        process.kill(pid, "SIGKILL");
      } catch {
        // gone
      }
    }
    await new Promise((resolve) => setTimeout(resolve, 10));
  }
  for (const folder of cgroup.folders) {
    try {
      fs.rmdirSync(folder);
    } catch {
      // still busy: left for the system
    }
  }
  cgroup = null;
}

// Whether a user other than the owner can reach `file` (every folder above it searchable
// by others, the file readable by others): nobody can bind it.
function othersCanRead(file) {
  for (let at = file; ; at = path.dirname(at)) {
    let mode;
    try {
      mode = fs.statSync(at).mode;
    } catch {
      return false;
    }
    const needed = at === file && !fs.statSync(at).isDirectory() ? 0o004 : 0o001;
    if ((mode & needed) === 0) return false;
    if (at === "/") return true;
  }
}

// A note's words where the sandbox is not bounded as a whole, else null.
function limitsNote() {
  if (why()) return null;
  return sandboxCgroup().note;
}

const real = (file) => {
  try {
    return fs.realpathSync(file);
  } catch {
    return null;
  }
};
const inside = (child, parent) =>
  child === parent || child.startsWith(parent === "/" ? "/" : parent + path.sep);
const system = (file) => SYSTEM.some((dir) => inside(file, dir));

// The shared libraries a program loads from outside the system's folders (pyenv's
// libpython), as ldd finds them.
function ownLibraries(program) {
  try {
    const text = execFileSync("ldd", [program], {
      encoding: "utf8",
      timeout: 10000,
      stdio: ["ignore", "pipe", "ignore"],
    });
    return [...text.matchAll(/=> (\/\S+)/g)]
      .map((match) => match[1])
      .filter((file) => !system(real(file) ?? file));
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
      const script =
        "import json, sys; print(json.dumps([sys.executable, sys.prefix, sys.base_prefix, [p for p in sys.path if p]]))";
      const text = execFileSync("python3", ["-c", script], {
        encoding: "utf8",
        timeout: 10000,
        stdio: ["ignore", "pipe", "ignore"],
        cwd: "/",
      });
      const [executable, prefix, basePrefix, importPath] = JSON.parse(text);
      const files = [
        executable,
        real(executable),
        path.join(prefix, "pyvenv.cfg"),
        ...importPath,
        ...ownLibraries(real(executable) ?? executable),
      ].filter((file) => file && fs.existsSync(file));
      // Searched for copies of the case files: the folders of the import path that are
      // not the installation's own (a virtual environment's packages, the user's,
      // PYTHONPATH's).
      const base = real(basePrefix) ?? basePrefix;
      const searched = importPath
        .map(real)
        .filter((dir) => dir && !inside(dir, base) && fs.statSync(dir).isDirectory());
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
  const searched =
    language === "python" ? (pythonInterpreter()?.searched ?? []) : modulePaths.map(real);
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
    const copy =
      (here.has("tests") && fs.existsSync(path.join(dir, "tests", "cases"))) ||
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
        if (entry.name === ".git" || (entry.name === "cases" && path.basename(dir) === "tests"))
          hidden.folders.add(file);
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
  if (folders.some((folder) => inside(CASES, folder) || inside(folder, CASES)))
    args.push("--tmpfs", CASES);
  // The hiding folders stay empty (a tmpfs the code could fill has no size): made
  // read-only once every mount is made (the runners' may be inside one).
  const readOnly = args.flatMap((word, at) =>
    word === "--tmpfs" ? ["--remount-ro", args[at + 1]] : [],
  );
  return { args, readOnly, cut: copies.cut };
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
  for (const file of [
    "/etc/ld.so.cache",
    "/etc/ld.so.conf",
    "/etc/ld.so.conf.d",
    "/etc/alternatives",
    "/etc/localtime",
  ]) {
    if (fs.existsSync(file)) args.push("--ro-bind", file, file);
  }
  return args;
}

// How many processes this user has now: the sandbox may add PROCESSES more (the limit
// counts all of the user's).
function userProcesses() {
  try {
    const uid = process.getuid();
    return fs
      .readdirSync("/proc")
      .filter((name) => /^\d+$/.test(name))
      .filter((name) => {
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
// empty; it says the sandbox's first process on file descriptor 6 (`{"child-pid": N}`).
// The command enters the sandbox's cgroup (a shell's `echo $$`) before anything else runs.
// `cut`: the search for copies of the case files stopped at its bound.
function sandboxed(command, { language, folders, seconds, modulePaths = [] }) {
  // A file outside the system's folders, or reached through a link from outside them (a
  // python3 in ~/bin that links to /usr/bin/python3): bound at its own path.
  const own = [...new Set(interpreterFiles(language, modulePaths))].filter(
    (file) => real(file) && !(system(file) && system(real(file))),
  );
  const bound = [...new Set([...folders, ...own.map(real)])];
  const hiding = hidingMounts(
    bound.filter((file) => fs.statSync(file).isDirectory()),
    [...new Set([...folders, ...interpreterSearched(language, modulePaths)])],
  );
  const env = Object.entries({
    PATH: "/usr/local/bin:/usr/bin:/bin",
    HOME: "/tmp",
    LANG: "C.UTF-8",
    ...command.env,
  }).flatMap(([name, value]) => ["--setenv", name, value]);
  const group = sandboxCgroup();
  const bwrap = [
    "--unshare-all",
    "--die-with-parent",
    "--new-session",
    "--clearenv",
    ...env,
    ...(isRoot() ? ["--unshare-user", "--uid", NOBODY, "--gid", NOBODY] : []),
    ...systemMounts(),
    "--proc",
    "/proc",
    "--dev",
    "/dev",
    "--size",
    `${TMP_BYTES}`,
    "--tmpfs",
    "/tmp",
    "--size",
    `${SHM_BYTES}`,
    "--tmpfs",
    "/dev/shm",
    ...own.flatMap((file) => ["--ro-bind", file, file]),
    ...folders.flatMap((dir) => ["--ro-bind", dir, dir]),
    ...hiding.args,
    "--ro-bind",
    RUNNERS,
    RUNNERS,
    ...hiding.readOnly,
    "--remount-ro",
    "/dev",
    "--remount-ro",
    "/",
    "--chdir",
    folders[0],
    "--info-fd",
    "6",
  ];
  const limits = [
    `--cpu=${Math.ceil(seconds)}`,
    `--fsize=${FILE_BYTES}`,
    ...(group.folders.length ? [] : [`--data=${MEMORY}`, `--nproc=${userProcesses() + PROCESSES}`]),
  ];
  // Root's processes are not counted against RLIMIT_NPROC: without a cgroup, root's
  // sandbox runs as nobody outside as well.
  const asNobody = isRoot() && group.folders.length === 0;
  const unreadable = asNobody
    ? [...bound, RUNNERS].find((file) => !othersCanRead(file))
    : undefined;
  if (unreadable) {
    return {
      refused: `run as root where no cgroup can be made, the checker runs your code as nobody (the kernel does not count root's processes), and nobody cannot read ${unreadable}: make it readable by others (chmod o+rX), or run the checker as a user`,
    };
  }
  const nobody = asNobody
    ? [located("setpriv"), `--reuid=${NOBODY}`, `--regid=${NOBODY}`, "--clear-groups", "--"]
    : [];
  const run = [
    located("prlimit"),
    ...limits,
    "--",
    ...nobody,
    located("bwrap"),
    "--args",
    "5",
    command.file,
    ...command.args,
  ];
  const enter = group.folders
    .map((folder) => `echo $$ > ${path.join(folder, "cgroup.procs")} && `)
    .join("");
  return {
    file: "/bin/sh",
    args: ["-c", `${enter}exec /usr/bin/env -i "$@"`, "sh", ...run],
    env: {},
    argsText: bwrap.map((word) => `${word}\0`).join(""),
    cut: hiding.cut,
  };
}

module.exports = { why, limitsNote, sandboxed, removeCgroup, pythonInterpreter, real };
