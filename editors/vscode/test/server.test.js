// The order in which the extension looks for the x3dcheck binary (out/server.js, the
// compiled src/server.ts: it does not need VS Code). Run after `npm run compile`.
const assert = require("node:assert");
const fs = require("node:fs");
const os = require("node:os");
const path = require("node:path");
const test = require("node:test");

const { findServer, INSTALL_HINT } = require("../out/server.js");

const EXE = process.platform === "win32" ? "x3dcheck.exe" : "x3dcheck";

function folderWithBinary(name) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), `x3dcheck-vscode-${name}-`));
  fs.writeFileSync(path.join(dir, EXE), "#!/bin/sh\n", { mode: 0o755 });
  return dir;
}

function withEnv(env, body) {
  const saved = { ...process.env };
  Object.assign(process.env, env);
  return body().finally(() => {
    process.env = saved;
  });
}

test("the setting wins, alone", async () => {
  const found = await findServer("/nonexistent", "/opt/x3dcheck");
  assert.deepStrictEqual(found, { command: "/opt/x3dcheck", source: "the x3dcheck.path setting" });
});

test("a bundled binary comes before PATH", async () => {
  const extension = fs.mkdtempSync(path.join(os.tmpdir(), "x3dcheck-vscode-ext-"));
  const server = path.join(extension, "server");
  fs.mkdirSync(server);
  fs.writeFileSync(path.join(server, EXE), "");
  const onPath = folderWithBinary("path");
  await withEnv({ PATH: onPath }, async () => {
    const found = await findServer(extension, undefined);
    assert.strictEqual(found.command, path.join(server, EXE));
  });
});

test("PATH, then nothing: the message says what to install", async () => {
  const onPath = folderWithBinary("path");
  await withEnv({ PATH: onPath, CARGO_HOME: "/nonexistent" }, async () => {
    const found = await findServer("/nonexistent", undefined);
    assert.deepStrictEqual(found, { command: path.join(onPath, EXE), source: "PATH" });
  });
  const empty = fs.mkdtempSync(path.join(os.tmpdir(), "x3dcheck-vscode-empty-"));
  await withEnv({ PATH: empty, CARGO_HOME: "/nonexistent" }, async () => {
    assert.strictEqual(await findServer("/nonexistent", undefined), undefined);
  });
  assert.match(INSTALL_HINT, /pip install x3dcheck/);
});

test("cargo's bin folder is the last place", async () => {
  const cargoHome = fs.mkdtempSync(path.join(os.tmpdir(), "x3dcheck-vscode-cargo-"));
  fs.mkdirSync(path.join(cargoHome, "bin"));
  fs.writeFileSync(path.join(cargoHome, "bin", EXE), "");
  const empty = fs.mkdtempSync(path.join(os.tmpdir(), "x3dcheck-vscode-empty-"));
  await withEnv({ PATH: empty, CARGO_HOME: cargoHome }, async () => {
    const found = await findServer("/nonexistent", undefined);
    assert.strictEqual(found.command, path.join(cargoHome, "bin", EXE));
  });
});
