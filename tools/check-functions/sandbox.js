// The sandbox a student's code runs in while the checker judges it: Debian's bubblewrap
// (bwrap) with the student's folder read-only (their code imports its own files), a
// private empty /tmp, no network, the system's programs and libraries read-only, and
// nothing else of the file system: not the repository's case files, not the checker. Its
// own PID namespace (it can neither signal the checker nor outlive it: it ends with
// it), its own session (it cannot write to the checker's terminal), and capped memory,
// CPU time and number of processes. Where bwrap cannot run, `why()` says why, in words
// for the report's first line, and the code runs as the user, as before.
"use strict";

const { execFileSync, spawnSync } = require("child_process");
const fs = require("fs");
const path = require("path");

const REPO = path.resolve(__dirname, "..", "..");
const RUNNERS = path.join(__dirname, "runners");
const MEMORY = 3 << 30;  // bytes of data a process may have (RLIMIT_DATA): a memory bomb ends in seconds
const PROCESSES = 256;  // processes the sandbox may add to the user's

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

let python = null;

// The python3 the user's PATH names, as the program it is (not a launcher such as
// pyenv's, which the sandbox could not run) and the directories it lives in; null when
// there is none.
function pythonInterpreter() {
  if (python === null) {
    try {
      const text = execFileSync("python3", ["-c", "import sys; print(sys.executable); print(sys.prefix); print(sys.base_prefix)"],
        { encoding: "utf8", timeout: 10000, stdio: ["ignore", "pipe", "ignore"] });
      const [executable, ...prefixes] = text.trim().split("\n");
      python = { executable, roots: [...prefixes, path.dirname(fs.realpathSync(executable))] };
    } catch {
      python = false;
    }
  }
  return python || null;
}

// The directories an interpreter lives in that the sandbox needs besides /usr: a Python
// of pyenv or a virtual environment, a Node.js outside /usr.
function interpreterRoots(language) {
  if (language === "python") return pythonInterpreter()?.roots ?? [];
  return [path.dirname(path.dirname(fs.realpathSync(process.execPath)))];
}

const inside = (child, parent) => child === parent || child.startsWith(parent + path.sep);

// The mounts that hide the repository from a folder of the student's that holds it.
function hideRepository(folders) {
  const args = [];
  if (folders.some((folder) => inside(REPO, folder))) {
    for (const entry of fs.readdirSync(REPO, { withFileTypes: true })) {
      if (entry.isDirectory()) args.push("--tmpfs", path.join(REPO, entry.name));
    }
  }
  const cases = path.join(REPO, "tests", "cases");
  if (folders.some((folder) => inside(cases, folder) || inside(folder, cases))) args.push("--tmpfs", cases);
  return args;
}

function systemMounts() {
  const args = ["--ro-bind", "/usr", "/usr"];
  for (const dir of ["/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"]) {
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

// The command that runs `command` ({ file, args, env }) in the sandbox, with `folders`
// (the student's) read-only and the working directory the first of them; the limits on
// the whole run, `seconds` of CPU time.
function sandboxed(command, { language, folders, seconds }) {
  const roots = [...new Set(interpreterRoots(language))].filter((dir) => dir && !inside(dir, "/usr") && fs.existsSync(dir));
  const env = Object.entries({ PATH: "/usr/local/bin:/usr/bin:/bin", HOME: "/tmp", LANG: "C.UTF-8", ...command.env })
    .flatMap(([name, value]) => ["--setenv", name, value]);
  const bwrap = [
    "--unshare-all", "--die-with-parent", "--new-session", "--clearenv", ...env,
    ...systemMounts(), "--proc", "/proc", "--dev", "/dev", "--tmpfs", "/tmp",
    ...roots.flatMap((dir) => ["--ro-bind", dir, dir]),
    ...folders.flatMap((dir) => ["--ro-bind", dir, dir]),
    ...hideRepository(folders),
    "--ro-bind", RUNNERS, RUNNERS,
    "--chdir", folders[0],
    command.file, ...command.args,
  ];
  const limits = [`--data=${MEMORY}`, `--cpu=${Math.ceil(seconds)}`, `--nproc=${userProcesses() + PROCESSES}`];
  return { file: "prlimit", args: [...limits, "--", "bwrap", ...bwrap], env: {} };
}

module.exports = { why, sandboxed, pythonInterpreter };
