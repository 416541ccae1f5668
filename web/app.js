// The x3dcheck web page: reads a dropped, chosen or pasted scene as bytes, checks it with
// the WebAssembly build of the checker (pkg/, written by web/build.sh) and shows the
// findings. Nothing is sent anywhere: the page has no server side.

const SEVERITIES = ["error", "warning", "info", "hint"];
const PLURAL = { error: "errors", warning: "warnings", info: "infos", hint: "hints" };
// Lines shown before and after a finding's line.
const CONTEXT_LINES = 1;

const $ = (id) => document.getElementById(id);

let checker = null;
const rulesByCode = new Map();
// The last check: its name, bytes, reports and decoded lines (for a level change, the
// excerpts and the downloads).
let current = null;
// Severities unticked in the filter; kept when another scene is checked.
const hiddenSeverities = new Set();

// The checker may hand back objects or JSON text; the page wants objects.
const asObject = (value) => (typeof value === "string" ? JSON.parse(value) : value);

function setStatus(text, isError = false) {
  const status = $("status");
  status.textContent = text;
  status.classList.toggle("error", isError);
}

function element(tag, attributes = {}, ...children) {
  const node = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) {
    if (name === "class") node.className = value;
    else if (name === "text") node.textContent = value;
    else node.setAttribute(name, value);
  }
  for (const child of children) {
    if (child != null) node.append(child);
  }
  return node;
}

// --- Loading the checker -----------------------------------------------------------------

async function loadChecker() {
  try {
    const module = await import("./pkg/x3dcheck_wasm.js");
    await module.default();
    checker = module;
  } catch (error) {
    setStatus(
      "The checker (pkg/x3dcheck_wasm.js) could not be loaded: run web/build.sh, then serve " +
        "web/ over HTTP (e.g. python3 -m http.server -d web). " + error,
      true,
    );
    return;
  }
  $("version").textContent = ` ${checker.version()}`;
  for (const rule of asObject(checker.rules())) rulesByCode.set(rule.code, rule);
  renderCatalogue();
  setStatus("Ready: drop, choose or paste a scene.");
  document.body.dataset.ready = "true";
  openRuleFromHash();
}

// --- Reading input -----------------------------------------------------------------------

const isGzip = (bytes) => bytes.length >= 2 && bytes[0] === 0x1f && bytes[1] === 0x8b;

async function gunzip(bytes) {
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream("gzip"));
  return new Uint8Array(await new Response(stream).arrayBuffer());
}

// The text the checker reads, decoded the same way as far as the browser can: a UTF-16
// byte-order mark, or the XML declaration's encoding, else UTF-8. Only the source excerpts
// use it; the checker decodes the bytes itself.
function decodeText(bytes) {
  let label = "utf-8";
  if (bytes[0] === 0xff && bytes[1] === 0xfe) label = "utf-16le";
  else if (bytes[0] === 0xfe && bytes[1] === 0xff) label = "utf-16be";
  else {
    const head = new TextDecoder("latin1").decode(bytes.subarray(0, 200));
    const declared = /^<\?xml[^>]*encoding\s*=\s*["']([A-Za-z0-9._-]+)["']/.exec(head);
    if (declared) label = declared[1];
  }
  try {
    return new TextDecoder(label).decode(bytes);
  } catch {
    return new TextDecoder("utf-8").decode(bytes);
  }
}

// A name for pasted text: its extension tells the checker the encoding.
function guessName(text) {
  const start = text.trimStart();
  if (start.startsWith("{")) return "pasted.x3dj";
  if (start.startsWith("#VRML")) return "pasted.wrl";
  if (start.startsWith("#X3D")) return "pasted.x3dv";
  return "pasted.x3d";
}

async function checkBytes(name, bytes) {
  if (!checker) return;
  setStatus(`Checking ${name}…`);
  const level = $("level").value;
  let report;
  let sarif;
  try {
    report = asObject(checker.check(bytes, { path: name, level, format: "json" }));
    sarif = asObject(checker.check(bytes, { path: name, level, format: "sarif" }));
  } catch (error) {
    setStatus(`The checker failed on ${name}: ${error}`, true);
    return;
  }
  let text = "";
  try {
    text = decodeText(isGzip(bytes) ? await gunzip(bytes) : bytes);
  } catch {
    // A damaged gzip stream: the report says so (GZIP_CORRUPT); there is no text to show.
  }
  current = { name, bytes, report, sarif, lines: text.split(/\r\n|\r|\n/) };
  renderReport();
  const s = report.summary;
  setStatus(
    `Checked ${name}: ${SEVERITIES.map((sev) => count(s[PLURAL[sev]], sev)).join(", ")}.`,
  );
}

const count = (n, severity) => `${n} ${n === 1 ? severity : PLURAL[severity]}`;

async function checkFile(file) {
  if (!file) return;
  const bytes = new Uint8Array(await file.arrayBuffer());
  await checkBytes(file.name, bytes);
}

// --- Showing the report ------------------------------------------------------------------

function renderReport() {
  const { report } = current;
  const diagnostics = report.files.flatMap((file) =>
    file.diagnostics.map((diagnostic) => ({ file, diagnostic })),
  );
  const first = report.files[0] ?? {};
  const facts = [
    first.encoding && `encoding ${first.encoding}${first.compressed ? " (gzip)" : ""}`,
    first.x3dVersion && `X3D ${first.x3dVersion}`,
    first.profile && `profile ${first.profile}`,
    first.stats && `${first.stats.nodes} nodes`,
  ].filter(Boolean);
  $("summary").textContent = `${current.name}: ${facts.join(", ")}`;

  renderFilters(report.summary);

  const list = $("findings");
  list.replaceChildren(
    ...diagnostics.map(({ file, diagnostic }) =>
      renderFinding(diagnostic, file.path === current.name ? null : file.path),
    ),
  );
  const empty = $("empty");
  empty.hidden = diagnostics.length > 0;
  empty.textContent = "No findings.";
  $("results").hidden = false;
  applyFilters();
}

function renderFilters(summary) {
  const fieldset = $("filters");
  fieldset.replaceChildren(element("legend", { text: "Show" }));
  for (const severity of SEVERITIES) {
    const n = summary[PLURAL[severity]] ?? 0;
    const box = element("input", {
      type: "checkbox",
      id: `show-${severity}`,
      "data-severity": severity,
    });
    box.checked = !hiddenSeverities.has(severity);
    box.addEventListener("change", () => {
      if (box.checked) hiddenSeverities.delete(severity);
      else hiddenSeverities.add(severity);
      applyFilters();
    });
    fieldset.append(
      element(
        "label",
        { class: `filter sev-${severity}`, for: `show-${severity}` },
        box,
        ` ${PLURAL[severity]} `,
        element("span", { class: "filter-count", text: `(${n})` }),
      ),
    );
  }
}

function applyFilters() {
  let visible = 0;
  for (const item of $("findings").children) {
    item.hidden = hiddenSeverities.has(item.dataset.severity);
    if (!item.hidden) visible += 1;
  }
  const total = $("findings").children.length;
  const empty = $("empty");
  empty.hidden = visible > 0;
  empty.textContent = total === 0 ? "No findings." : "Every finding is filtered out.";
}

function renderFinding(d, otherFile) {
  const rule = rulesByCode.get(d.code);
  const place = `${d.line}:${d.column}`;
  const head = element(
    "div",
    { class: "finding-head" },
    element("span", { class: `badge sev-${d.severity}`, text: d.severity }),
    element("a", { class: "code", href: `#rule-${d.code}`, text: d.code }),
    element("span", { class: "place", text: otherFile ? `${otherFile}:${place}` : place }),
    d.clause ? element("span", { class: "clause", text: `clause ${d.clause}` }) : null,
  );
  const message = element("p", { class: "message", text: d.message });
  if (d.count > 1) message.append(element("span", { class: "count", text: ` (×${d.count})` }));
  const item = element(
    "li",
    {
      class: `finding sev-${d.severity}`,
      "data-severity": d.severity,
      "data-code": d.code,
      "data-line": String(d.line),
      "data-column": String(d.column),
    },
    head,
    message,
  );
  if (!otherFile) item.append(renderExcerpt(d));
  if (d.help) item.append(element("p", { class: "help", text: `help: ${d.help}` }));
  for (const related of d.related ?? []) {
    item.append(
      element("p", {
        class: "related",
        text: `see ${related.line}:${related.column}: ${related.message}`,
      }),
    );
  }
  if (d.path) item.append(element("p", { class: "path", text: d.path }));
  if (rule) item.append(renderRuleToggle(rule));
  return item;
}

// The finding's line with the ones around it; the finding's columns are marked on its
// first line (columns count Unicode scalar values, as Array.from does).
function renderExcerpt(d) {
  const lines = current.lines;
  const pre = element("pre", { class: "excerpt" });
  if (d.line < 1 || d.line > lines.length) return pre;
  const from = Math.max(1, d.line - CONTEXT_LINES);
  const to = Math.min(lines.length, d.line + CONTEXT_LINES);
  const width = String(to).length;
  for (let number = from; number <= to; number += 1) {
    const text = lines[number - 1];
    const row = element("span", { class: number === d.line ? "line target" : "line" });
    row.append(element("span", { class: "number", text: String(number).padStart(width) }));
    if (number === d.line) {
      const chars = Array.from(text);
      const start = Math.max(0, d.column - 1);
      const end = d.endLine === d.line ? Math.max(start + 1, d.endColumn - 1) : chars.length;
      row.append(
        chars.slice(0, start).join(""),
        element("mark", { text: chars.slice(start, end).join("") || " " }),
        chars.slice(end).join(""),
      );
    } else {
      row.append(text);
    }
    pre.append(row, "\n");
  }
  return pre;
}

function renderRuleToggle(rule) {
  const details = element(
    "details",
    { class: "rule-doc" },
    element("summary", { text: `About ${rule.code}` }),
  );
  details.addEventListener(
    "toggle",
    () => {
      if (details.open && details.childElementCount === 1) details.append(renderDoc(rule));
    },
  );
  return details;
}

function renderDoc(rule) {
  const body = element("div", { class: "doc" });
  body.append(
    element("p", {
      class: "doc-facts",
      text: `${rule.severity}, level ${rule.level}, X3D ${rule.versions}, clause ${rule.clause}`,
    }),
  );
  body.append(markdown(rule.doc ?? ""));
  return body;
}

// --- The rule catalogue ------------------------------------------------------------------

function renderCatalogue() {
  const container = $("rules");
  const items = [];
  for (const rule of rulesByCode.values()) {
    const details = element(
      "details",
      { class: "rule", id: `rule-${rule.code}` },
      element(
        "summary",
        {},
        element("span", { class: `badge sev-${rule.severity}`, text: rule.severity }),
        element("code", { text: rule.code }),
        ` ${rule.summary}`,
      ),
    );
    details.addEventListener("toggle", () => {
      if (details.open && details.childElementCount === 1) details.append(renderDoc(rule));
    });
    items.push(details);
  }
  container.replaceChildren(...items);
  $("rules-count").textContent = `${items.length} rules.`;
}

function openRuleFromHash() {
  const match = /^#rule-([A-Z0-9_]+)$/.exec(location.hash);
  if (!match) return;
  const details = document.getElementById(`rule-${match[1]}`);
  if (!details) return;
  details.open = true;
  details.scrollIntoView({ block: "start" });
}

// The rule docs are a small Markdown subset: `## ` headings, ``` fences, `> ` quotes,
// `- ` lists, paragraphs, and `code` inline. Text goes in as text nodes: no HTML.
function markdown(source) {
  const fragment = document.createDocumentFragment();
  const lines = source.split("\n");
  let index = 0;
  let paragraph = [];
  const flush = () => {
    if (paragraph.length) fragment.append(inline("p", paragraph.join(" ")));
    paragraph = [];
  };
  while (index < lines.length) {
    const line = lines[index];
    if (line.startsWith("```")) {
      flush();
      const code = [];
      index += 1;
      while (index < lines.length && !lines[index].startsWith("```")) code.push(lines[index++]);
      fragment.append(element("pre", { class: "doc-code" }, element("code", { text: code.join("\n") })));
    } else if (/^#{1,6} /.test(line)) {
      flush();
      fragment.append(inline("h4", line.replace(/^#+ /, "")));
    } else if (line.startsWith(">")) {
      flush();
      const quote = [];
      while (index < lines.length && lines[index].startsWith(">")) {
        quote.push(lines[index++].replace(/^> ?/, ""));
      }
      index -= 1;
      fragment.append(element("blockquote", {}, inline("p", quote.join(" "))));
    } else if (/^[-*] /.test(line)) {
      flush();
      const list = element("ul");
      while (index < lines.length && /^([-*] |  )/.test(lines[index])) {
        if (/^[-*] /.test(lines[index])) list.append(inline("li", lines[index].slice(2)));
        else list.lastChild.append(" " + lines[index].trim());
        index += 1;
      }
      index -= 1;
      fragment.append(list);
    } else if (line.trim() === "") {
      flush();
    } else {
      paragraph.push(line);
    }
    index += 1;
  }
  flush();
  return fragment;
}

function inline(tag, text) {
  const node = element(tag);
  text.split(/(`[^`]+`)/).forEach((part, i) => {
    node.append(i % 2 ? element("code", { text: part.slice(1, -1) }) : part);
  });
  return node;
}

// --- Downloads ---------------------------------------------------------------------------

function download(kind) {
  if (!current) return;
  const isSarif = kind === "sarif";
  const data = isSarif ? current.sarif : current.report;
  const blob = new Blob([JSON.stringify(data, null, 2) + "\n"], {
    type: isSarif ? "application/sarif+json" : "application/json",
  });
  const url = URL.createObjectURL(blob);
  const link = element("a", {
    href: url,
    download: `${current.name}.${isSarif ? "sarif" : "x3dcheck.json"}`,
  });
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(url), 0);
}

// --- Wiring ------------------------------------------------------------------------------

function wire() {
  const drop = $("dropzone");
  const input = $("file");
  input.addEventListener("change", () => checkFile(input.files[0]));
  // A file dropped anywhere is checked (and does not replace the page); the zone only
  // shows where to drop. Text dragged into the paste box keeps its default.
  const hasFiles = (event) => event.dataTransfer?.types.includes("Files");
  window.addEventListener("dragover", (event) => {
    if (hasFiles(event)) event.preventDefault();
  });
  window.addEventListener("drop", (event) => {
    if (!hasFiles(event)) return;
    event.preventDefault();
    drop.classList.remove("dragging");
    checkFile(event.dataTransfer.files[0]);
  });
  drop.addEventListener("dragenter", () => drop.classList.add("dragging"));
  drop.addEventListener("dragleave", () => drop.classList.remove("dragging"));
  $("level").addEventListener("change", () => {
    if (current) checkBytes(current.name, current.bytes);
  });
  $("paste-check").addEventListener("click", () => {
    const text = $("paste-text").value;
    const name = $("paste-name").value.trim() || guessName(text);
    checkBytes(name, new TextEncoder().encode(text));
  });
  $("download-json").addEventListener("click", () => download("json"));
  $("download-sarif").addEventListener("click", () => download("sarif"));
  window.addEventListener("hashchange", openRuleFromHash);
}

wire();
loadChecker();
