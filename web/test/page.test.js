// The web page in a real headless Chromium (Debian's /usr/bin/chromium, or $CHROMIUM),
// driven by playwright-core: load web/ from a local server, drop or choose known-bad
// scenes of corpus/rules/, check the findings shown, the severity filter, the rule docs
// and the two downloads. Needs web/pkg/ (web/build.sh). Run: `node --test` in web/test.

import { after, before, test } from "node:test";
import assert from "node:assert/strict";
import { createServer } from "node:http";
import { existsSync } from "node:fs";
import { mkdtemp, readFile, rm } from "node:fs/promises";
import { tmpdir } from "node:os";
import { dirname, extname, join, normalize, resolve, sep } from "node:path";
import { fileURLToPath } from "node:url";
import { gzipSync } from "node:zlib";
import { chromium } from "playwright-core";

const WEB = resolve(dirname(fileURLToPath(import.meta.url)), "..");
const RULES = resolve(WEB, "..", "corpus", "rules");
const CHROMIUM = process.env.CHROMIUM ?? "/usr/bin/chromium";

// The XML scene: one warning and one error.
const XML_SCENE = join(RULES, "BACK_MATERIAL_WITH_TWO_SIDED", "fail.x3d");
const XML_FINDINGS = [
  { severity: "warning", code: "NODE_DEPRECATED", line: 6 },
  { severity: "error", code: "BACK_MATERIAL_WITH_TWO_SIDED", line: 7 },
];
// The ClassicVRML scene: two errors, numbers among comments.
const CLASSIC_SCENE = join(RULES, "FIELD_OUT_OF_RANGE", "fail_comment_in_value.x3dv");
const CLASSIC_FINDINGS = [
  { severity: "error", code: "FIELD_OUT_OF_RANGE", line: 10 },
  { severity: "error", code: "FIELD_OUT_OF_RANGE", line: 18 },
];

const MIME = {
  ".html": "text/html; charset=utf-8",
  ".js": "text/javascript; charset=utf-8",
  ".css": "text/css; charset=utf-8",
  ".json": "application/json",
  ".wasm": "application/wasm",
  ".ts": "text/plain; charset=utf-8",
};

let server;
let origin;
let context;
let profile;
let page;
const offsiteRequests = [];

// web/, read-only; anything outside it is a 404.
function serve(request, response) {
  const path = decodeURIComponent(new URL(request.url, "http://localhost").pathname);
  const file = normalize(join(WEB, path.endsWith("/") ? `${path}index.html` : path));
  if (!file.startsWith(WEB + sep)) {
    response.writeHead(404).end();
    return;
  }
  readFile(file).then(
    (body) => {
      response.writeHead(200, { "content-type": MIME[extname(file)] ?? "application/octet-stream" });
      response.end(body);
    },
    () => response.writeHead(404).end(),
  );
}

before(async () => {
  assert.ok(
    existsSync(join(WEB, "pkg", "x3dcheck_wasm.js")),
    "web/pkg/x3dcheck_wasm.js is missing: run web/build.sh first",
  );
  server = createServer(serve);
  await new Promise((done) => server.listen(0, "127.0.0.1", done));
  origin = `http://127.0.0.1:${server.address().port}`;

  profile = await mkdtemp(join(tmpdir(), "x3dcheck-web-test-"));
  context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    acceptDownloads: true,
    viewport: { width: 1100, height: 900 },
    args: [
      "--headless",
      "--no-sandbox",
      "--disable-gpu",
      "--disable-quic",
      "--no-first-run",
      "--disable-background-networking",
      "--disable-component-update",
      "--disable-sync",
    ],
  });
  page = context.pages()[0] ?? (await context.newPage());
  page.on("request", (request) => {
    const url = request.url();
    if (!url.startsWith(origin) && !url.startsWith("blob:") && !url.startsWith("data:")) {
      offsiteRequests.push(url);
    }
  });
  const problems = [];
  page.on("pageerror", (error) => problems.push(String(error)));
  await page.goto(`${origin}/`);
  await page.waitForSelector("body[data-ready='true']", { timeout: 30_000 }).catch(() => {
    throw new Error(`the page did not get ready: ${problems.join("; ")}`);
  });
});

after(async () => {
  await context?.close();
  await new Promise((done) => (server ? server.close(done) : done()));
  if (profile) await rm(profile, { recursive: true, force: true });
});

// What the page shows: one entry per finding, hidden ones included.
const shownFindings = () =>
  page.$$eval("#findings > li", (items) =>
    items.map((item) => ({
      severity: item.dataset.severity,
      code: item.dataset.code,
      line: Number(item.dataset.line),
      hidden: item.hidden,
    })),
  );

const withoutHidden = (findings) => findings.map(({ hidden, ...rest }) => rest);

async function waitForChecked(name) {
  await page.waitForFunction(
    (expected) => document.getElementById("status").textContent.startsWith(`Checked ${expected}:`),
    name,
  );
}

async function dropFile(name, bytes) {
  const dataTransfer = await page.evaluateHandle(
    ({ name, data }) => {
      const transfer = new DataTransfer();
      transfer.items.add(new File([new Uint8Array(data)], name));
      return transfer;
    },
    { name, data: [...bytes] },
  );
  await page.dispatchEvent("#dropzone", "dragenter", { dataTransfer });
  await page.dispatchEvent("#dropzone", "drop", { dataTransfer });
}

async function downloadJson(button) {
  const [download] = await Promise.all([page.waitForEvent("download"), page.click(button)]);
  return { name: download.suggestedFilename(), data: JSON.parse(await readFile(await download.path(), "utf8")) };
}

test("the rule catalogue and the version are shown", async () => {
  const rules = await page.$$eval("#rules > details.rule", (items) => items.map((item) => item.id));
  assert.ok(rules.length > 100, `${rules.length} rules`);
  assert.ok(rules.includes("rule-BACK_MATERIAL_WITH_TWO_SIDED"));
  assert.match(await page.textContent("#version"), /^ \d+\.\d+\.\d+/);
});

test("a dropped XML scene: findings with line, source, clause, filter, rule doc", async () => {
  await dropFile("fail.x3d", await readFile(XML_SCENE));
  await waitForChecked("fail.x3d");
  assert.deepEqual(withoutHidden(await shownFindings()), XML_FINDINGS);

  const error = page.locator("#findings > li[data-code='BACK_MATERIAL_WITH_TWO_SIDED']");
  assert.equal(await error.locator(".place").textContent(), "7:9");
  assert.equal(await error.locator(".clause").textContent(), "clause 12.2.3");
  const excerpt = await error.locator(".excerpt").textContent();
  assert.match(excerpt, /6 +<TwoSidedMaterial/);
  assert.match(excerpt, /7 +<Material containerField='backMaterial'/);
  assert.match(excerpt, /8 +<\/Appearance>/);
  assert.match(await error.locator(".excerpt mark").textContent(), /^<Material containerField/);
  assert.equal(await error.locator(".code").getAttribute("href"), "#rule-BACK_MATERIAL_WITH_TWO_SIDED");

  // The rule's doc, in the page.
  await error.locator(".rule-doc summary").click();
  assert.match(await error.locator(".rule-doc .doc").textContent(), /What it does/);

  // The severity filter: counts, and unticking errors leaves the warning.
  assert.equal(await page.textContent("label[for='show-error']"), " errors (1)");
  assert.equal(await page.textContent("label[for='show-warning']"), " warnings (1)");
  assert.equal(await page.textContent("label[for='show-info']"), " infos (0)");
  await page.uncheck("#show-error");
  assert.deepEqual(
    (await shownFindings()).filter((f) => !f.hidden).map((f) => f.code),
    ["NODE_DEPRECATED"],
  );
  assert.equal(await page.isVisible("#findings > li[data-code='BACK_MATERIAL_WITH_TWO_SIDED']"), false);
  await page.uncheck("#show-warning");
  assert.equal(await page.textContent("#empty"), "Every finding is filtered out.");
  await page.check("#show-error");
  await page.check("#show-warning");
  assert.ok((await shownFindings()).every((f) => !f.hidden));

  if (process.env.X3DCHECK_WEB_SCREENSHOT) {
    await page.locator("#results").screenshot({ path: process.env.X3DCHECK_WEB_SCREENSHOT });
  }
});

test("the JSON and SARIF downloads hold the findings shown", async () => {
  const shown = withoutHidden(await shownFindings());

  const json = await downloadJson("#download-json");
  assert.equal(json.name, "fail.x3d.x3dcheck.json");
  assert.equal(json.data.tool, "x3dcheck");
  assert.deepEqual(
    json.data.files.flatMap((file) =>
      file.diagnostics.map(({ severity, code, line }) => ({ severity, code, line })),
    ),
    shown,
  );

  const sarif = await downloadJson("#download-sarif");
  assert.equal(sarif.name, "fail.x3d.sarif");
  assert.equal(sarif.data.version, "2.1.0");
  const results = sarif.data.runs.flatMap((run) => run.results);
  assert.deepEqual(
    results.map((result) => ({
      code: result.ruleId,
      line: result.locations[0].physicalLocation.region.startLine,
    })),
    shown.map(({ code, line }) => ({ code, line })),
  );
});

test("a gzip-compressed scene chosen in the file input: the same findings, source shown; another level", async () => {
  await page.setInputFiles("#file", {
    name: "fail.x3dz",
    mimeType: "application/gzip",
    buffer: gzipSync(await readFile(XML_SCENE)),
  });
  await waitForChecked("fail.x3dz");
  assert.match(await page.textContent("#summary"), /encoding xml \(gzip\)/);
  assert.deepEqual(withoutHidden(await shownFindings()), XML_FINDINGS);
  assert.match(
    await page.textContent("#findings > li[data-code='NODE_DEPRECATED'] .excerpt mark"),
    /^TwoSidedMaterial$/,
  );

  // Another level checks the same bytes again: fast has no cross-node rule.
  await page.selectOption("#level", "fast");
  await page.waitForFunction(() => document.querySelectorAll("#findings > li").length === 1);
  assert.deepEqual(withoutHidden(await shownFindings()), [XML_FINDINGS[0]]);
  await page.selectOption("#level", "standard");
  await page.waitForFunction(() => document.querySelectorAll("#findings > li").length === 2);
});

test("a ClassicVRML scene, chosen and then pasted", async () => {
  await page.setInputFiles("#file", CLASSIC_SCENE);
  await waitForChecked("fail_comment_in_value.x3dv");
  assert.deepEqual(withoutHidden(await shownFindings()), CLASSIC_FINDINGS);
  assert.equal(await page.textContent("label[for='show-error']"), " errors (2)");

  await page.click("#paste-details summary");
  await page.fill("#paste-text", await readFile(CLASSIC_SCENE, "utf8"));
  await page.click("#paste-check");
  await waitForChecked("pasted.x3dv");
  assert.deepEqual(withoutHidden(await shownFindings()), CLASSIC_FINDINGS);
  assert.match(
    await page.textContent("#findings > li[data-line='18'] .excerpt"),
    /18 +0 0 -1 \] \}/,
  );
});

test("nothing was requested from anywhere but the page's own server", () => {
  assert.deepEqual(offsiteRequests, []);
});
