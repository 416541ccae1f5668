// Finds the x3dcheck binary the extension starts as `x3dcheck server`, in this order:
// the `x3dcheck.path` setting when the user set one; a binary bundled in the extension
// (`server/x3dcheck`, in platform-specific packages); `x3dcheck` on PATH; the places pip
// installs console scripts to (the user scheme, then each Python's own scripts folder);
// cargo's bin folder. Nothing is downloaded.

import { execFile } from "child_process";
import * as fs from "fs";
import * as os from "os";
import * as path from "path";

const EXE = process.platform === "win32" ? "x3dcheck.exe" : "x3dcheck";

/** Where a binary was found, and how (for the output channel). */
export interface Found {
  command: string;
  source: string;
}

function isFile(candidate: string): boolean {
  try {
    return fs.statSync(candidate).isFile();
  } catch {
    return false;
  }
}

function onPath(): string | undefined {
  const dirs = (process.env.PATH ?? "").split(path.delimiter).filter(Boolean);
  return dirs.map((dir) => path.join(dir, EXE)).find(isFile);
}

/** Runs `python -c code` and returns its stdout lines, or [] when there is no such Python. */
function pythonLines(python: string, code: string): Promise<string[]> {
  return new Promise((resolve) => {
    execFile(python, ["-c", code], { timeout: 5000 }, (error, stdout) => {
      resolve(error ? [] : stdout.split(/\r?\n/).filter(Boolean));
    });
  });
}

/** The folders pip puts console scripts in, for each Python on PATH. */
async function pipScriptFolders(): Promise<string[]> {
  const code = [
    "import os, sysconfig",
    "print(sysconfig.get_path('scripts', os.name + '_user') or '')",
    "print(sysconfig.get_path('scripts') or '')",
  ].join("\n");
  const pythons = process.platform === "win32" ? ["py", "python"] : ["python3", "python"];
  const folders: string[] = [];
  for (const python of pythons) {
    folders.push(...(await pythonLines(python, code)));
  }
  return [...new Set(folders)];
}

/**
 * The binary to start, or undefined when none is installed. `configured` is the setting's
 * value when the user set one (an explicit choice is tried alone, so a wrong path is
 * reported rather than silently replaced).
 */
export async function findServer(
  extensionPath: string,
  configured: string | undefined
): Promise<Found | undefined> {
  if (configured) {
    return { command: configured, source: "the x3dcheck.path setting" };
  }
  const bundled = path.join(extensionPath, "server", EXE);
  if (isFile(bundled)) {
    return { command: bundled, source: "bundled with the extension" };
  }
  const fromPath = onPath();
  if (fromPath) {
    return { command: fromPath, source: "PATH" };
  }
  for (const folder of await pipScriptFolders()) {
    const candidate = path.join(folder, EXE);
    if (isFile(candidate)) {
      return { command: candidate, source: `pip's scripts folder ${folder}` };
    }
  }
  const cargo = path.join(process.env.CARGO_HOME ?? path.join(os.homedir(), ".cargo"), "bin", EXE);
  if (isFile(cargo)) {
    return { command: cargo, source: "cargo's bin folder" };
  }
  return undefined;
}

/** What the user reads when no binary is found. */
export const INSTALL_HINT =
  "x3dcheck: no x3dcheck binary found (looked in the extension, on PATH, in pip's and " +
  "cargo's folders). Install it with `pip install x3dcheck` (a prebuilt wheel, no " +
  "compiler), or `cargo install --locked --path .` in an x3dcheck checkout, then reload " +
  "the window; or set x3dcheck.path to the binary.";
