// node render.mjs JOBS.json: renders every job of JOBS.json with three.js in
// headless Chromium (page.html) and writes each job's PNG to job.out.
// `arcomp-bench gltf-reference` writes the jobs file and calls this; by
// hand it is a way to look at one model the way three.js draws it.
//
// JOBS.json: { "chromium": "/usr/bin/chromium",
//              "jobs": [ { "model": "/abs/x.gltf", "out": "/abs/x.png", "width": 480, "height": 360,
//                          "eye": [x, y, z], "target": [x, y, z], "fovy": 40, "near": 0.1, "far": 100,
//                          "light": { "direction": [x, y, z], "color": [r, g, b], "intensity": 3 },
//                          "environment": "/abs/env.hdr" | null, "environmentIntensity": 1,
//                          "time": 0.5 | null } ] }
// Last line of stdout: {"three": "<REVISION>", "gl": "<WebGL renderer>", "rendered": N}.
//
// Chromium has no GPU here: WebGL runs on SwiftShader through ANGLE, which
// recent Chromium only allows with --enable-unsafe-swiftshader.

import { chromium } from 'playwright-core';
import { createServer } from 'node:http';
import { readFile, writeFile, mkdir } from 'node:fs/promises';
import { dirname, join, extname } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const types = { '.html': 'text/html', '.js': 'text/javascript', '.gltf': 'model/gltf+json', '.glb': 'model/gltf-binary',
                '.bin': 'application/octet-stream', '.hdr': 'application/octet-stream', '.png': 'image/png',
                '.wasm': 'application/wasm' };

if (process.argv.length !== 3) {
  console.error('usage: node render.mjs JOBS.json');
  process.exit(2);
}
const jobsFile = process.argv[2];
const spec = JSON.parse(await readFile(jobsFile, 'utf8'));

// The page may fetch only the files the jobs name (by number), three.js
// itself (its Draco decoder included) and the page: a model's data is
// embedded, so nothing else is needed.
const files = [];
const urlOf = (path) => {
  if (path === null || path === undefined) return null;
  let i = files.indexOf(path);
  if (i < 0) i = files.push(path) - 1;
  return `/file/${i}${extname(path)}`;
};
const jobs = spec.jobs.map((job) => ({ ...job, model: urlOf(job.model), environment: urlOf(job.environment) }));

const server = createServer(async (request, response) => {
  const path = decodeURIComponent(new URL(request.url, 'http://localhost').pathname);
  let file = null;
  if (path === '/page.html') file = join(here, 'page.html');
  else if (path.startsWith('/three/') && !path.includes('..')) file = join(here, 'node_modules', path);
  else if (path.startsWith('/file/')) file = files[Number.parseInt(path.slice(6), 10)] ?? null;
  if (!file) {
    response.writeHead(404).end();
    return;
  }
  try {
    const body = await readFile(file);
    response.writeHead(200, { 'content-type': types[extname(file)] ?? 'application/octet-stream' }).end(body);
  } catch (e) {
    response.writeHead(404).end(String(e));
  }
});
await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
const origin = `http://127.0.0.1:${server.address().port}`;

const browser = await chromium.launch({
  executablePath: spec.chromium ?? '/usr/bin/chromium',
  headless: true,
  args: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist', '--no-sandbox'],
});
let failed = false;
try {
  const page = await browser.newPage();
  page.on('console', (m) => { if (m.type() === 'error' || m.type() === 'warning') console.error(`page ${m.type()}: ${m.text()}`); });
  page.on('pageerror', (e) => { console.error(`page error: ${e.message}`); failed = true; });
  await page.goto(`${origin}/page.html`);
  await page.waitForFunction(() => window.pageReady === true, null, { timeout: 30000 });
  for (let i = 0; i < jobs.length; ++i) {
    const png = await page.evaluate((job) => window.renderJob(job), jobs[i]);
    const out = spec.jobs[i].out;
    await mkdir(dirname(out), { recursive: true });
    await writeFile(out, Buffer.from(png.slice(png.indexOf(',') + 1), 'base64'));
  }
  const info = await page.evaluate(() => window.rendererInfo());
  console.log(JSON.stringify({ ...info, rendered: jobs.length }));
} catch (e) {
  console.error(`three.js reference failed (${jobsFile}): ${e.message}`);
  failed = true;
} finally {
  await browser.close();
  server.close();
}
process.exit(failed ? 1 : 0);
