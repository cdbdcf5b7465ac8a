// Headless Chromium, driven through its DevTools protocol, for the site's tests
// (check_site.mjs, check_your_code.mjs, check_models.mjs): one page, its pages opened
// from the site's folder, keys, mouse drags, files chosen, and what the page evaluates.
// Every request the browser makes is heard: one that leaves this machine (anything but a
// file of the site, a Blob, data or 127.0.0.1) is kept in `outside`, for a test to fail on.
import { spawn, execFileSync } from "node:child_process";
import { mkdtempSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join } from "node:path";

export const sleep = (ms) => new Promise((done) => setTimeout(done, ms));
let failures = 0;
export function fail(line) {
  console.log(`FAIL: ${line}`);
  ++failures;
}
export const failureCount = () => failures;

// Chromium, and one page of it, spoken to through --remote-debugging-pipe: the
// browser reads commands from its file descriptor 3 and writes its answers to 4, each
// message JSON ended by a NUL byte (no WebSocket, so any Node.js from 18 on will do).
export class Browser {
  static async open(site) {
    const profile = mkdtempSync(join(tmpdir(), "cgfs-site-"));
    const binary = ["chromium", "chromium-browser"].find((name) => {
      try {
        execFileSync("sh", ["-c", `command -v ${name}`]);
        return true;
      } catch {
        return false;
      }
    });
    if (!binary) {
      console.log(
        "check_site: no Chromium to load the pages in: install the Debian package chromium",
      );
      globalThis.process.exit(2);
    }
    const process = spawn(
      binary,
      [
        "--headless",
        "--no-sandbox",
        "--disable-gpu",
        "--hide-scrollbars",
        "--window-size=1400,1000",
        "--remote-debugging-pipe",
        `--user-data-dir=${profile}`,
        "about:blank",
      ],
      { stdio: ["ignore", "ignore", "ignore", "pipe", "pipe"] },
    );
    const browser = new Browser(process, profile, site);
    const { targetId } = await browser.send("Target.createTarget", { url: "about:blank" });
    browser.session = (
      await browser.send("Target.attachToTarget", { targetId, flatten: true })
    ).sessionId;
    await browser.send("Page.enable");
    await browser.hearRequests(browser.session);
    return browser;
  }

  constructor(process, profile, site) {
    Object.assign(this, {
      process,
      profile,
      site,
      next: 1,
      waiting: new Map(),
      session: undefined,
      outside: [],
    });
    let unread = "";
    process.stdio[3].on("error", () => {}); // once the browser has quit
    process.stdio[4].setEncoding("utf8");
    process.stdio[4].on("data", (chunk) => {
      const messages = (unread + chunk).split("\0");
      unread = messages.pop();
      for (const text of messages) this.answer(JSON.parse(text));
    });
  }

  // Every request of a session (the page's, and each of its workers'), heard; the
  // workers' sessions are attached to as they start.
  async hearRequests(session) {
    await this.send("Network.enable", {}, session);
    await this.send(
      "Target.setAutoAttach",
      { autoAttach: true, waitForDebuggerOnStart: true, flatten: true },
      session,
    );
  }

  event(message) {
    if (message.method === "Network.requestWillBeSent") {
      const url = message.params.request.url;
      if (
        !/^(file|blob|data|about|chrome|devtools):|^https?:\/\/(127\.0\.0\.1|localhost)[:/]/.test(
          url,
        )
      )
        this.outside.push(url);
    } else if (message.method === "Target.attachedToTarget") {
      const session = message.params.sessionId;
      this.hearRequests(session)
        .catch(() => {})
        .finally(() => this.send("Runtime.runIfWaitingForDebugger", {}, session).catch(() => {}));
    }
  }

  answer(message) {
    if (message.id === undefined) {
      this.event(message);
      return;
    }
    const waiter = this.waiting.get(message.id);
    if (waiter) {
      this.waiting.delete(message.id);
      message.error
        ? waiter.reject(new Error(message.error.message))
        : waiter.resolve(message.result);
    }
  }

  send(method, params = {}, session = this.session) {
    const id = this.next++;
    this.process.stdio[3].write(JSON.stringify({ id, method, params, sessionId: session }) + "\0");
    return new Promise((resolve, reject) => this.waiting.set(id, { resolve, reject }));
  }

  // The value of a JavaScript expression in the page (awaited when it is a promise).
  async evaluate(expression) {
    const { result, exceptionDetails } = await this.send("Runtime.evaluate", {
      expression,
      awaitPromise: true,
      returnByValue: true,
    });
    if (exceptionDetails)
      throw new Error(`${expression}: ${exceptionDetails.exception?.description}`);
    return result.value;
  }

  // The page's canvas as [width, height, SHA-256 of its RGBA pixels], as PngDigest
  // (png.mjs) gives a PNG file's.
  async canvasDigest() {
    return this.evaluate(`(async () => {
      const canvas = document.getElementById('canvas');
      const pixels = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
      const digest = new Uint8Array(await crypto.subtle.digest('SHA-256', pixels));
      return [canvas.width, canvas.height, Array.from(digest, (b) => b.toString(16).padStart(2, '0')).join('')];
    })()`);
  }

  async waitFor(expression, what, seconds = 60) {
    for (let waited = 0; waited < seconds * 1000; waited += 50) {
      if (await this.evaluate(expression)) return true;
      await sleep(50);
    }
    fail(`${what}: not within ${seconds} s`);
    return false;
  }

  async open(page) {
    const url = `file://${this.site}/${page}`;
    await this.send("Page.navigate", { url });
    // The page keeps the figure shown in its address: compared without the query.
    const bare = url.replace(/[?#].*$/, "");
    return this.waitFor(
      `location.href.replace(/[?#].*$/, '') === ${JSON.stringify(bare)} && document.readyState === 'complete' && ` +
        "(document.getElementById('live')?.dataset.ready === 'yes' || " +
        "!document.getElementById('status')?.textContent.startsWith('Loading'))",
      `${page} loads`,
    );
  }

  async key(key) {
    const named = {
      ArrowUp: 38,
      ArrowDown: 40,
      ArrowLeft: 37,
      ArrowRight: 39,
      PageUp: 33,
      PageDown: 34,
      Home: 36,
      End: 35,
    };
    const code = named[key] ?? key.toUpperCase().charCodeAt(0);
    const common = {
      key,
      windowsVirtualKeyCode: code,
      code: named[key] ? key : `Key${key.toUpperCase()}`,
    };
    await this.send("Input.dispatchKeyEvent", {
      type: "keyDown",
      ...common,
      text: named[key] ? undefined : key,
    });
    await this.send("Input.dispatchKeyEvent", { type: "keyUp", ...common });
  }

  // Chooses files in the page's file input `selector`, as a reader does in the browser's
  // file picker (its change event follows).
  async chooseFiles(selector, paths) {
    const { result } = await this.send("Runtime.evaluate", {
      expression: `document.querySelector(${JSON.stringify(selector)})`,
    });
    await this.send("DOM.setFileInputFiles", { files: paths, objectId: result.objectId });
  }

  async drag(fromX, fromY, right, down) {
    const mouse = (type, x, y, buttons) =>
      this.send("Input.dispatchMouseEvent", { type, x, y, button: "left", buttons, clickCount: 1 });
    await mouse("mousePressed", fromX, fromY, 1);
    for (let step = 1; step <= 4; ++step) {
      await mouse("mouseMoved", fromX + (right * step) / 4, fromY + (down * step) / 4, 1);
    }
    await mouse("mouseReleased", fromX + right, fromY + down, 0);
  }

  // Asks Chromium to quit, and removes its profile once its last process has left it.
  async close() {
    const exited = new Promise((done) => this.process.once("exit", done));
    this.session = undefined;
    this.send("Browser.close").catch(() => {});
    await Promise.race([exited, sleep(10000)]);
    this.process.kill();
    rmSync(this.profile, { recursive: true, force: true, maxRetries: 50, retryDelay: 100 });
  }
}
