// A chapter written as a web page, loaded outside a browser: its scripts, in order (the
// page they expect is page_stand_in.mjs's).

import fs from "node:fs";
import path from "node:path";

// The page's scripts in order: inline ones with the line they start on, and local files
// named by src (a chapter kept in raytracer.js beside its page).
export function pageScripts(html, file) {
  const scripts = [];
  const pattern = /<script\b([^>]*)>([\s\S]*?)<\/script\s*>/gi;
  for (let match; (match = pattern.exec(html)) !== null;) {
    const src = /\bsrc\s*=\s*["']?([^"'\s>]+)/i.exec(match[1])?.[1];
    if (/\btype\s*=\s*["']?(module|text\/(?!javascript))/i.test(match[1])) continue;
    if (src) {
      if (/^[a-z]+:/i.test(src)) continue; // another site's: not the chapter
      const local = path.resolve(path.dirname(file), src);
      scripts.push({ code: fs.readFileSync(local, "utf8"), line: 0, filename: local });
    } else {
      const before = html.slice(0, match.index + match[0].indexOf(">") + 1);
      scripts.push({ code: match[2], line: before.split("\n").length - 1, filename: file });
    }
  }
  return scripts;
}
