// `fluence review` in headless Chromium (puppeteer-core): the page's pixels must equal OCIO's CPU
// transform of the same EXR (review_reference) within 1/255 for several views, exposures and
// gammas, the A/B wipe must show image A left of the wipe and image B right of it, and the static
// export must open from disk (file://) and show the same pixels.
//   node review_browser_test.mjs FLUENCE REVIEW_REFERENCE CHROMIUM WORK_DIR
import { spawn, execFileSync } from 'node:child_process';
import { createRequire } from 'node:module';
import { copyFileSync, mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { pathToFileURL } from 'node:url';

const [fluence, reference, chromium, work] = process.argv.slice(2);
const puppeteer = createRequire(join(work, 'package.json'))('puppeteer-core');
const scratch = mkdtempSync(join(work, 'run-'));
const sourceDir = new URL('../..', import.meta.url).pathname;
let failures = 0;

function check(ok, what) {
  console.log((ok ? 'ok      ' : 'FAILED  ') + what);
  if (!ok) failures += 1;
}

function render(name, extra, env = process.env) {
  const out = join(scratch, name);
  execFileSync(fluence, ['render', join(sourceDir, 'usd_samples/cornell_box.usda'), '-o', out, '-r', '48', '36',
                         '--spp', '4', ...extra], { stdio: 'pipe', env });
  return out;
}

function referencePixels(exr, display, view, look, exposure, gamma, env = process.env) {
  return new Uint8Array(execFileSync(reference, [exr, display, view, look, String(exposure), String(gamma)],
                                     { maxBuffer: 1 << 28, env }));
}

// An OCIO config whose views are LUTs (a 17^3 .cube, trilinear; a 1D .spi1d, linear) and which has a
// look (a CDL), so that the shader's LUT textures and the look menu are exercised.
function writeLutConfig(dir) {
  mkdirSync(dir);
  const n = 17;
  let cube = `LUT_3D_SIZE ${n}\n`;
  for (let b = 0; b < n; ++b)
    for (let g = 0; g < n; ++g)
      for (let r = 0; r < n; ++r) {
        const [x, y, z] = [r / (n - 1), g / (n - 1), b / (n - 1)];
        cube += `${Math.sqrt(x).toFixed(6)} ${(0.7 * y + 0.3 * z * z).toFixed(6)} ${Math.sqrt(z * x).toFixed(6)}\n`;
      }
  writeFileSync(join(dir, 'view.cube'), cube);
  const values = Array.from({ length: 64 }, (_, i) => Math.pow(i / 63, 1 / 2.6).toFixed(6));
  writeFileSync(join(dir, 'curve.spi1d'),
                `Version 1\nFrom 0.0 1.0\nLength 64\nComponents 1\n{\n${values.join('\n')}\n}\n`);
  writeFileSync(join(dir, 'lut.ocio'), `ocio_profile_version: 2
search_path: "."
roles:
  default: lin_rec709
  scene_linear: lin_rec709
file_rules:
  - !<Rule> {name: Default, colorspace: lin_rec709}
displays:
  Projector:
    - !<View> {name: Cube, colorspace: cube_display}
    - !<View> {name: Curve, colorspace: curve_display}
active_displays: []
active_views: []
looks:
  - !<Look> {name: Warm, process_space: lin_rec709, transform: !<CDLTransform> {slope: [1.2, 1.0, 0.8]}}
colorspaces:
  - !<ColorSpace> {name: lin_rec709, isdata: false}
  - !<ColorSpace>
    name: cube_display
    from_reference: !<FileTransform> {src: view.cube, interpolation: linear}
  - !<ColorSpace>
    name: curve_display
    from_reference: !<FileTransform> {src: curve.spi1d, interpolation: linear}
`);
  return join(dir, 'lut.ocio');
}

// The largest difference of the RGB of `shown` and `expected`, over the pixel columns [x0, x1).
function maxDifference(shown, expected, width, x0 = 0, x1 = width) {
  let worst = 0;
  for (let i = 0; i < expected.length; i += 4) {
    const x = (i / 4) % width;
    if (x < x0 || x >= x1) continue;
    for (let c = 0; c < 3; ++c) worst = Math.max(worst, Math.abs(shown[i + c] - expected[i + c]));
  }
  return worst;
}

function startServer(files) {
  return new Promise((resolve, reject) => {
    const server = spawn(fluence, ['review', ...files], { stdio: ['ignore', 'pipe', 'inherit'] });
    let text = '';
    server.stdout.on('data', (chunk) => {
      text += chunk;
      const url = text.match(/http:\/\/\S+\//);
      if (url) resolve({ server, url: url[0] });
    });
    server.on('exit', (code) => reject(new Error('fluence review exited with ' + code)));
  });
}

async function choose(page, id, value) {
  await page.evaluate(async (id, value) => {
    const element = document.getElementById(id);
    element.value = value;
    element.dispatchEvent(new Event(id === 'exposure' || id === 'gamma' || id === 'wipe' ? 'input' : 'change'));
    await new Promise((r) => setTimeout(r, 0));
  }, id, String(value));
}

async function openPage(browser, url) {
  const page = await browser.newPage();
  await page.setViewport({ width: 900, height: 600 });
  page.on('pageerror', (e) => console.log('page error: ' + e.message));
  await page.goto(url);
  await page.evaluate(() => window.fluenceReviewReady);
  return page;
}

async function shown(page) {
  await page.evaluate(() => window.fluenceReview.pending);
  return new Uint8Array(await page.evaluate(() => Array.from(window.fluenceReview.displayedPixels())));
}

const settings = [
  ['sRGB', 'Standard', '', 0, 1],
  ['sRGB', 'Standard', '', 1.5, 1],
  ['sRGB', 'Raw', '', -1, 1],
  ['sRGB', 'Standard', '', -0.5, 2.2],
];

async function checkViews(page, exr, where, cases = settings, env = process.env) {
  for (const [display, view, look, exposure, gamma] of cases) {
    await choose(page, 'display', display);
    await choose(page, 'view', view);
    await choose(page, 'look', look);
    await choose(page, 'exposure', exposure);
    await choose(page, 'gamma', gamma);
    const width = await page.evaluate(() => window.fluenceReview.image.width);
    const d = maxDifference(await shown(page), referencePixels(exr, display, view, look, exposure, gamma, env), width);
    check(d <= 1, `${where}: ${display}/${view} exposure ${exposure} gamma ${gamma}: largest difference ${d}/255`);
  }
}

const a = render('a.exr', ['--seed', '1', '--cryptomatte', 'object']);
const b = render('b.exr', ['--seed', '2', '--spp', '1']);
// A folder holding a two-frame sequence, for the flipbook.
const shots = join(scratch, 'shots');
mkdirSync(shots);
copyFileSync(a, join(shots, 'seq.0001.exr'));
copyFileSync(b, join(shots, 'seq.0002.exr'));
const aHalf = join(scratch, 'a_half.exr');
execFileSync('oiiotool', [a, '-d', 'half', '-o', aHalf]);
const lutEnv = { ...process.env, OCIO: writeLutConfig(join(scratch, 'ocio')) };
const lut = render('lut.exr', ['--seed', '3'], lutEnv);
const { server, url } = await startServer([a, b, aHalf, lut, shots]);
const browser = await puppeteer.launch({
  executablePath: chromium, headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--allow-file-access-from-files'],
});
try {
  const page = await openPage(browser, url);
  await checkViews(page, a, 'server');

  // A half-float EXR reaches the page losslessly: its pixels too equal OCIO's CPU transform.
  await choose(page, 'file', 'a_half.exr');
  const halfFormat = await page.evaluate(() => window.fluenceReview.pending.then(
      () => window.fluenceReview.image.layers.find((l) => l.name === 'rgba').format));
  check(halfFormat === 'half', `a_half.exr's beauty arrives as ${halfFormat}`);
  await checkViews(page, aHalf, 'half-float EXR');

  // An image rendered under another config ($OCIO, named in its header): that config's menus, its
  // 3D and 1D LUTs uploaded as textures with their interpolation, and its look.
  await choose(page, 'file', 'lut.exr');
  await page.evaluate(() => window.fluenceReview.pending);
  const menus = await page.evaluate(() => [document.getElementById('display').textContent,
                                           document.getElementById('look').textContent]);
  check(menus[0] === 'Projector' && menus[1] === '(none)Warm', `lut.exr's menus: ${JSON.stringify(menus)}`);
  await checkViews(page, lut, 'LUT config', [['Projector', 'Cube', '', 0, 1], ['Projector', 'Curve', '', 0.5, 1],
                                             ['Projector', 'Cube', 'Warm', -0.5, 1.5]], lutEnv);
  const luts = await page.evaluate(() => window.fluenceReview.ocio.textures.map((t) => [t.depth, t.linear]));
  check(luts.length === 1 && luts[0][0] === 17 && luts[0][1], `the Cube view's shader has its 17^3 LUT: ${luts}`);

  // Pixel values under the pointer, and the wheel zooming by 2 about the pointer.
  await choose(page, 'file', 'a_half.exr');
  await page.evaluate(() => window.fluenceReview.pending);
  await page.evaluate(() => { window.fluenceReview.zoom = 1; window.fluenceReview.origin = [0, 0]; });
  await choose(page, 'exposure', 0);
  await choose(page, 'gamma', 1);
  const corner = await page.evaluate(() => { const r = document.getElementById('canvas').getBoundingClientRect();
                                             return [r.left, r.top]; });
  const halfReference = referencePixels(aHalf, 'sRGB', 'Standard', '', 0, 1);
  const at = (x, y) => Array.from(halfReference.subarray((y * 48 + x) * 4, (y * 48 + x) * 4 + 3)).join(' ');
  await page.mouse.move(corner[0] + 20.5, corner[1] + 10.5);
  const readout = await page.evaluate(() => document.getElementById('pixel').textContent);
  check(readout.startsWith('x 20 y 10\nlinear   R ') && readout.endsWith('displayed ' + at(20, 10)),
        `pixel readout at 20,10: ${JSON.stringify(readout)}`);
  await page.mouse.wheel({ deltaY: -100 });
  await page.mouse.move(corner[0] + 20.5 + 8, corner[1] + 10.5 + 6);  // 4, 3 image pixels further at zoom 2
  const zoomed = await page.evaluate(() => document.getElementById('pixel').textContent);
  check(zoomed.startsWith('x 24 y 13\n') && zoomed.endsWith('displayed ' + at(24, 13)),
        `after zooming in about 20,10, 8,6 screen pixels further: ${JSON.stringify(zoomed)}`);
  await choose(page, 'file', 'a.exr');
  await page.evaluate(() => window.fluenceReview.pending);

  // A/B wipe at the middle: A's pixels left of it, B's right of it.
  await choose(page, 'exposure', 0);
  await choose(page, 'gamma', 1);
  await choose(page, 'view', 'Standard');
  await choose(page, 'compare', 'b.exr');
  await choose(page, 'wipe', 0.5);
  const width = await page.evaluate(() => window.fluenceReview.image.width);
  const wiped = await shown(page);
  const left = maxDifference(wiped, referencePixels(a, 'sRGB', 'Standard', '', 0, 1), width, 0, width / 2);
  const right = maxDifference(wiped, referencePixels(b, 'sRGB', 'Standard', '', 0, 1), width, width / 2, width);
  const bothDiffer = maxDifference(referencePixels(a, 'sRGB', 'Standard', '', 0, 1),
                                   referencePixels(b, 'sRGB', 'Standard', '', 0, 1), width, width / 2, width);
  check(left <= 1 && right <= 1 && bothDiffer > 1,
        `A/B wipe: A left (${left}/255), B right (${right}/255), A and B differ there (${bothDiffer}/255)`);

  // The difference view in false colour: against an identical copy every pixel shows 0 (dark
  // blue, 0 0 128); against b the differences show.
  await choose(page, 'mode', 3);
  await choose(page, 'compare', 'shots/seq.0001.exr');
  const same = await shown(page);
  const zero = new Uint8Array(same.length).map((_, i) => [0, 0, 128, 255][i % 4]);
  check(maxDifference(same, zero, width) <= 1, 'difference of an image and its copy is 0 everywhere');
  await choose(page, 'compare', 'b.exr');
  check(maxDifference(await shown(page), zero, width) > 50, 'difference of a and b shows where they differ');
  await choose(page, 'mode', 1);

  // A Cryptomatte click at 1:1 selects the prim under the pointer: the floor at the bottom middle,
  // the left wall near the left edge, the ceiling at the top middle.
  await choose(page, 'compare', '');
  await page.evaluate(() => { window.fluenceReview.zoom = 1; window.fluenceReview.origin = [0, 0]; });
  const box = await page.evaluate(() => { const r = document.getElementById('canvas').getBoundingClientRect();
                                          return [r.left, r.top]; });
  for (const [x, y, prim] of [[24, 34, '/CornellBox/Geometry/Floor'], [8, 18, '/CornellBox/Geometry/LeftWall'],
                              [24, 1, '/CornellBox/Geometry/Ceiling']]) {
    await page.mouse.click(box[0] + x + 0.5, box[1] + y + 0.5);
    await page.evaluate(() => window.fluenceReview.pending);
    const picked = await page.evaluate(() => document.getElementById('matte').textContent);
    check(picked === 'CryptoObject: ' + prim, `Cryptomatte click at ${x},${y}: '${picked}'`);
  }
  const overlaid = await shown(page);
  const plain = referencePixels(a, 'sRGB', 'Standard', '', 0, 1);
  check(maxDifference(overlaid, plain, width) > 20, 'the picked matte is drawn over the image');

  // relMSE against a reference: b (1 spp) against a (4 spp) is positive, a copy of a is 0.
  await choose(page, 'reference', 'a.exr');
  await page.evaluate(() => window.fluenceReview.pending);
  const errors = Object.fromEntries(await page.evaluate(() => Array.from(
      document.getElementById('errors').rows, (r) => [r.cells[0].textContent, Number(r.cells[1].textContent)])));
  check(errors['b.exr'] > 0 && errors['shots/seq.0001.exr'] === 0,
        `relMSE against a.exr: b.exr ${errors['b.exr']}, its copy shots/seq.0001.exr ${errors['shots/seq.0001.exr']}`);

  // The flipbook plays the folder's sequence: both frames are shown within a second at 24 fps.
  await page.evaluate(() => window.fluenceReview.show('shots/seq.0001.exr'));
  await page.evaluate(() => window.fluenceReview.pending);
  const seen = await page.evaluate(async () => {
    const frames = new Set();
    document.getElementById('play').click();
    const end = performance.now() + 1000;
    while (performance.now() < end) {
      frames.add(document.getElementById('status').textContent);
      await new Promise((r) => setTimeout(r, 10));
    }
    document.getElementById('play').click();
    return [...frames].filter((t) => t.startsWith('frame ')).sort();
  });
  check(seen.length === 2 && seen[0] === 'frame 1 (24 fps)' && seen[1] === 'frame 2 (24 fps)',
        `flipbook over shots/seq.####.exr shows both frames: ${JSON.stringify(seen)}`);

  // The static export, opened from disk.
  const exported = join(scratch, 'static');
  execFileSync(fluence, ['review', a, '--static', exported], { stdio: 'pipe' });
  const staticPage = await openPage(browser, pathToFileURL(join(exported, 'index.html')).href);
  await checkViews(staticPage, a, 'static export (file://)');
} finally {
  await browser.close();
  server.kill('SIGTERM');
  rmSync(scratch, { recursive: true, force: true });
}
console.log(failures ? `${failures} check(s) failed` : 'all checks passed');
process.exit(failures ? 1 : 0);
