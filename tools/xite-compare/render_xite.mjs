// Renders scenes with X_ITE (npm package x_ite) in Debian's headless Chromium, driven by
// playwright-core, and saves a screenshot of the X3D canvas per scene.
//
//   node render_xite.mjs --corpus DIR --out DIR [--size 400x300]
//                        SCENE...            (paths relative to --corpus)
//
// The corpus and X_ITE are served from a localhost HTTP server of this script (relative
// textures and Inlines load as on a web site); every request to any other host is aborted,
// so nothing reaches the network. Prints one JSON line per scene on stdout:
// {"scene", "png", "ms", "error", "console"}.

import { createServer } from "node:http";
import { createReadStream, mkdirSync, statSync } from "node:fs";
import { dirname, extname, join, resolve, sep } from "node:path";
import { fileURLToPath } from "node:url";
import { chromium } from "playwright-core";

const here = dirname(fileURLToPath(import.meta.url));

function parseArgs(argv) {
   const args = { size: "400x300", scenes: [], timeout: 60000 };
   for (let i = 0; i < argv.length; i++) {
      const a = argv[i];
      if (a === "--corpus") args.corpus = resolve(argv[++i]);
      else if (a === "--out") args.out = resolve(argv[++i]);
      else if (a === "--size") args.size = argv[++i];
      else if (a === "--timeout-ms") args.timeout = Number(argv[++i]);
      else if (a.startsWith("--")) throw new Error(`unknown option ${a}`);
      else args.scenes.push(a);
   }
   if (!args.corpus || !args.out) throw new Error("--corpus and --out are required");
   const [w, h] = args.size.split("x").map(Number);
   args.width = w;
   args.height = h;
   return args;
}

const types = {
   ".html": "text/html", ".js": "text/javascript", ".mjs": "text/javascript",
   ".css": "text/css", ".png": "image/png", ".jpg": "image/jpeg", ".jpeg": "image/jpeg",
   ".gif": "image/gif", ".x3d": "model/x3d+xml", ".x3dv": "model/x3d-vrml",
   ".wrl": "model/vrml", ".json": "application/json", ".x3dj": "model/x3d+json",
   ".gz": "application/gzip", ".ttf": "font/ttf", ".otf": "font/otf", ".woff2": "font/woff2",
};

// /corpus/… from the corpus, /x_ite/… from the package, /page.html from this directory.
function serve(corpus) {
   const roots = {
      "/corpus/": corpus,
      "/x_ite/": join(here, "node_modules", "x_ite", "dist"),
      "/": here,
   };
   const server = createServer((req, res) => {
      const path = decodeURIComponent(new URL(req.url, "http://localhost").pathname);
      const prefix = Object.keys(roots).find(p => path.startsWith(p));
      const file = resolve(roots[prefix], "." + sep + path.slice(prefix.length));
      if (!file.startsWith(roots[prefix]) || (prefix === "/" && !file.endsWith("page.html"))) {
         res.writeHead(403).end();
         return;
      }
      try {
         if (!statSync(file).isFile()) throw new Error("not a file");
      } catch {
         res.writeHead(404).end();
         return;
      }
      res.writeHead(200, { "Content-Type": types[extname(file).toLowerCase()] ?? "application/octet-stream" });
      createReadStream(file).pipe(res);
   });
   return new Promise(ok => server.listen(0, "127.0.0.1", () => ok(server)));
}

// In the page: load the scene, wait until X_ITE has loaded everything it counts (textures,
// Inlines, external prototypes) and drawn a few frames.
async function loadInPage({ url, width, height }) {
   const canvas = document.getElementById("scene");
   canvas.style.width = `${width}px`;
   canvas.style.height = `${height}px`;
   const browser = X3D.getBrowser(canvas);
   // x3dcheck's balanced preset lights per pixel; X_ITE's default is Gouraud.
   browser.setBrowserOption("Shading", "PHONG");
   // Spheres, cones and cylinders closest to the true surface.
   browser.setBrowserOption("PrimitiveQuality", "HIGH");
   // The view compared is the bound Viewpoint's: no falling of a WALK viewer (23.4.4
   // terrain following) over the frames before the screenshot.
   browser.setBrowserOption("Gravity", 0);
   await browser.loadURL(new X3D.MFString(url));
   for (let i = 0; i < 4; i++) await browser.nextFrame();
}

async function main() {
   const args = parseArgs(process.argv.slice(2));
   mkdirSync(args.out, { recursive: true });
   const server = await serve(args.corpus);
   const origin = `http://127.0.0.1:${server.address().port}`;
   const chrome = await chromium.launch({
      executablePath: "/usr/bin/chromium",
      args: [
         "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         // WebGL on SwiftShader, the same software rasterizer on every machine.
         "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
      ],
   });
   try {
      for (const scene of args.scenes) {
         const started = Date.now();
         const context = await chrome.newContext({
            viewport: { width: args.width, height: args.height },
            deviceScaleFactor: 1,
         });
         const page = await context.newPage();
         const consoleLines = [];
         page.on("console", m => {
            if ((m.type() === "error" || m.type() === "warning") && !m.text().includes("GL Driver Message")) consoleLines.push(m.text().slice(0, 300));
         });
         page.on("pageerror", e => consoleLines.push(String(e).slice(0, 300)));
         await page.route("**/*", route =>
            route.request().url().startsWith(origin + "/") ? route.continue() : route.abort());
         const png = join(args.out, scene.replaceAll("/", "__") + ".png");
         let error = null;
         try {
            await page.goto(`${origin}/page.html`);
            await page.waitForFunction(() => typeof X3D !== "undefined");
            let timer;
            await Promise.race([
               page.evaluate(loadInPage, {
                  url: `${origin}/corpus/${scene.split("/").map(encodeURIComponent).join("/")}`,
                  width: args.width,
                  height: args.height,
               }),
               new Promise((_, no) => {
                  timer = setTimeout(() => no(new Error(`timed out after ${args.timeout} ms`)), args.timeout);
               }),
            ]).finally(() => clearTimeout(timer));
            await page.locator("#scene canvas").first().screenshot({ path: png });
         } catch (e) {
            error = String(e.message ?? e).split("\n")[0];
         }
         await context.close();
         console.log(JSON.stringify({ scene, png: error ? null : png, ms: Date.now() - started, error, console: consoleLines }));
      }
   } finally {
      await chrome.close();
      server.closeAllConnections();
      server.close();
   }
}

await main();
