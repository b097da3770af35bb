// The dashboard in a real browser: Debian's chromium driven by playwright-core against a real
// getme-server running real smoothing jobs posted from the page.
//   node dashboard_test.mjs GETME_SERVER OUTPUT_DIR
// Exit 0 when every check passed, 1 otherwise, 77 (ctest SKIP_RETURN_CODE) without chromium.
// OUTPUT_DIR receives the server log and screenshots for a human look.
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';

const [serverBinary, outputDir] = process.argv.slice(2);
const chromiumPath = process.env.GETME_CHROMIUM || '/usr/bin/chromium';
if (!serverBinary || !outputDir) {
  console.error('usage: node dashboard_test.mjs GETME_SERVER OUTPUT_DIR');
  process.exit(2);
}
if (!fs.existsSync(chromiumPath)) {
  console.log(`SKIP: ${chromiumPath} not found; install Debian's chromium (scripts/setup.sh does)`);
  process.exit(77);
}
const { chromium } = await import('playwright-core');
fs.mkdirSync(outputDir, { recursive: true });

let passed = 0;
let failed = 0;
function check(name, ok, detail = '') {
  if (ok) passed += 1;
  else failed += 1;
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${name}${detail ? `: ${detail}` : ''}`);
}

// getme-server on free loopback ports; resolves with the dashboard URL from its log.
function startServer(extraArgs = [], logName = 'server.log') {
  const log = fs.createWriteStream(path.join(outputDir, logName));
  const server = spawn(serverBinary, ['--listen=127.0.0.1:0', '--http_listen=127.0.0.1:0',
    '--workers=2', '--progress_interval=50ms', '--shutdown_grace=1s', ...extraArgs],
  { stdio: ['ignore', 'ignore', 'pipe'] });
  const url = new Promise((resolve, reject) => {
    let text = '';
    server.stderr.on('data', (chunk) => {
      log.write(chunk);
      text += chunk;
      const match = /HTTP gateway and dashboard at (http:\/\/\S+\/)/.exec(text);
      if (match) resolve(match[1]);
    });
    server.on('exit', (code) => reject(new Error(`getme-server exited (${code}): ${text}`)));
    setTimeout(() => reject(new Error(`getme-server did not start: ${text}`)), 20000);
  });
  return { server, url };
}

const chartPoints = (page) => page.$eval('#chart', (svg) => Number(svg.dataset.points));
const shownState = (page) => page.textContent('#job-state');

async function fillDemoForm(page, {
  cells, method, simultaneous, sequential, boundary = 'BOUNDARY_FIXED', keepLayers = false,
}) {
  await page.fill('input[name=cells]', String(cells));
  await page.selectOption('select[name=method]', method);
  await page.fill('input[name=simultaneous]', String(simultaneous));
  await page.fill('input[name=sequential]', String(sequential));
  await page.selectOption('select[name=boundary]', boundary);
  await page.setChecked('input[name=keepLayers]', keepLayers);
}

async function submitDemoJob(page, options) {
  await fillDemoForm(page, options);
  await page.click('#demo-submit');
  await page.waitForFunction(() => /queued/.test(document.getElementById('demo-status').textContent));
  return page.textContent('#job-id');
}

const { server, url: serverUrl } = startServer();
let authServer = null;
const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'getme-chromium-'));
let context;
try {
  const url = await serverUrl;
  context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: chromiumPath,
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  const page = context.pages()[0] || await context.newPage();
  page.setDefaultTimeout(60000);
  page.on('pageerror', (error) => check('no script errors on the page', false, error.message));
  await page.goto(url);
  check('dashboard loads', (await page.title()).includes('getme'));

  // 1. A GETMe job of a few seconds: the chart grows while it runs, the histogram appears.
  // 2,000 simultaneous iterations (tolerance 0) keep it running for seconds on a quiet machine.
  const first = await submitDemoJob(page, {
    cells: 12, method: 'METHOD_GETME', simultaneous: 2000, sequential: 60000,
  });
  await page.waitForFunction(() => Number(document.getElementById('chart').dataset.points) > 2);
  const early = await chartPoints(page);
  // The state shown at the moment the chart first has more points than `early`.
  const stateWhenGrown = await (await page.waitForFunction((n) => {
    const points = Number(document.getElementById('chart').dataset.points);
    return points > n ? document.getElementById('job-state').textContent : null;
  }, early, { polling: 50 })).jsonValue();
  const later = await chartPoints(page);
  check('chart gains points while the job runs', later > early && stateWhenGrown === 'RUNNING',
    `${early} → ${later} points, state ${stateWhenGrown}`);
  await page.waitForSelector('#histogram[data-ready="true"]', { timeout: 120000 });
  const bars = await page.$$eval('#histogram rect.bar-after', (rects) => rects.length);
  const beforeBars = await page.$$eval('#histogram rect.bar-before', (rects) => rects.length);
  check('final histogram shows before and after', bars === 20 && beforeBars === 20,
    `${beforeBars} before, ${bars} after bins`);
  await page.waitForFunction(() => document.getElementById('job-state').textContent === 'SUCCEEDED');
  const phases = await page.$$eval('#chart rect.phase', (rects) => rects.map((r) => r.dataset.phase));
  check('every phase is marked', phases.includes('PHASE_SIMULTANEOUS') &&
    phases.includes('PHASE_SEQUENTIAL') && phases.includes('PHASE_POLISH'), phases.join(', '));
  await page.screenshot({ path: path.join(outputDir, 'dashboard-succeeded.png'), fullPage: true });

  // 2. A job that would run for minutes: cancel it from the page.
  const second = await submitDemoJob(page, {
    cells: 8, method: 'METHOD_SEQUENTIAL', simultaneous: 1, sequential: 1000000000,
  });
  await page.waitForFunction(() => document.getElementById('job-state').textContent === 'RUNNING');
  await page.click('#cancel');
  await page.waitForFunction(() => document.getElementById('job-state').textContent === 'CANCELLED');
  const api = await (await fetch(`${url}v1/jobs/${second}`)).json();
  check('cancel shows CANCELLED in the page and the API', api.state === 'JOB_STATE_CANCELLED',
    api.state);
  await page.waitForFunction((id) => {
    const row = document.querySelector(`tr[data-job-id="${id}"] .state`);
    return row && row.textContent === 'CANCELLED';
  }, second);
  check('job list shows the cancelled job', true);

  // 3. A reload keeps the selection (URL hash) and the job list; the finished job's histogram
  // comes back from its event stream.
  await page.reload();
  await page.waitForFunction(() => document.getElementById('job-state').textContent === 'CANCELLED');
  // The list comes from its own request (GET /v1/jobs), which may land after the selected job's.
  const listed = await page.waitForFunction(([a, b]) => {
    const ids = [...document.querySelectorAll('#jobs tbody tr')].map((tr) => tr.dataset.jobId);
    return ids.includes(a) && ids.includes(b);
  }, [first, second], { timeout: 10000 }).then(() => true, () => false);
  const rows = await page.$$eval('#jobs tbody tr', (trs) => trs.map((tr) => tr.dataset.jobId));
  check('after a reload the list has both jobs', listed, rows.join(', '));
  await page.click(`tr[data-job-id="${first}"]`);
  await page.waitForSelector('#histogram[data-ready="true"]');
  check('after a reload a finished job shows its histogram again', true);
  await page.waitForFunction((n) => Number(document.getElementById('chart').dataset.points) >= n,
    later);
  check('after a reload its chart is drawn from the start (trace)', true);
  await page.screenshot({ path: path.join(outputDir, 'dashboard-reloaded.png'), fullPage: true });

  // 4. A server with bearer tokens: the page asks for one, then lists, runs and streams a job
  // (the event stream's token travels as a query parameter).
  const token = 'browser-test-token-0123456789';
  const tokensFile = path.join(outputDir, 'tokens.txt');
  fs.writeFileSync(tokensFile, `browser:${token}\n`);
  const started = startServer([`--auth_tokens_file=${tokensFile}`], 'server-auth.log');
  authServer = started.server;
  const authPage = await context.newPage();
  authPage.setDefaultTimeout(60000);
  await authPage.goto(await started.url);
  await authPage.waitForSelector('#token-panel:not([hidden])');
  check('with auth on the page asks for a token', true);
  await authPage.fill('input[name=token]', token);
  await authPage.click('#token-form button');
  await authPage.waitForSelector('#token-panel', { state: 'hidden' });
  const authJob = await submitDemoJob(authPage, {
    cells: 4, method: 'METHOD_SIMULTANEOUS', simultaneous: 50, sequential: 1,
  });
  await authPage.waitForFunction(() => document.getElementById('job-state').textContent === 'SUCCEEDED');
  await authPage.waitForSelector('#histogram[data-ready="true"]');
  check('with a token the page runs a job and streams its events', true, authJob);
  const unauthorized = await fetch(`${await started.url}v1/jobs`);
  check('without a token the API answers 401', unauthorized.status === 401, String(unauthorized.status));

  // 5. The bare page (no job in the URL) opens on the newest job's live chart with no click: the
  // running job, although a newer one has already finished; then it follows a job submitted
  // later, until the user picks one by hand.
  const running = await submitDemoJob(page, {
    cells: 8, method: 'METHOD_SEQUENTIAL', simultaneous: 1, sequential: 1000000000,
  });
  await page.waitForFunction(() => document.getElementById('job-state').textContent === 'RUNNING');
  const finished = await submitDemoJob(page, {
    cells: 4, method: 'METHOD_SIMULTANEOUS', simultaneous: 50, sequential: 1,
  });
  await page.waitForFunction(() => document.getElementById('job-state').textContent === 'SUCCEEDED');
  const bare = await context.newPage();
  bare.setDefaultTimeout(60000);
  bare.on('pageerror', (error) => check('no script errors on the bare page', false, error.message));
  await bare.goto(url);
  const opened = await bare.waitForFunction((id) => {
    const panel = document.getElementById('job-panel');
    const points = Number(document.getElementById('chart').dataset.points);
    return !panel.hidden && document.getElementById('job-id').textContent === id && points > 0
      ? points : null;
  }, running, { timeout: 10000 }).then((handle) => handle.jsonValue(), () => 0);
  const bareState = await shownState(bare);
  check('the bare page opens on the running job\'s chart with no click',
    opened > 0 && bareState === 'RUNNING',
    `job ${await bare.textContent('#job-id')} (running ${running}, newer finished ${finished}), ` +
    `${opened} points, state ${bareState}`);
  const grew = await bare.waitForFunction((n) => Number(document.getElementById('chart').dataset.points) > n,
    opened, { timeout: 10000 }).then(() => true, () => false);
  check('its chart follows the running job live', grew, `${opened} → ${await chartPoints(bare)} points`);
  await bare.screenshot({ path: path.join(outputDir, 'dashboard-bare.png'), fullPage: true });
  const newer = await submitDemoJob(page, {
    cells: 4, method: 'METHOD_SIMULTANEOUS', simultaneous: 50, sequential: 1,
  });
  const followed = await bare.waitForFunction((id) => document.getElementById('job-id').textContent === id,
    newer, { timeout: 10000 }).then(() => true, () => false);
  check('the bare page follows a newer job', followed && (await bare.evaluate(() => location.hash)) === '',
    `shows ${await bare.textContent('#job-id')}, expected ${newer}`);
  await bare.click(`tr[data-job-id="${finished}"]`);
  const ignored = await submitDemoJob(page, {
    cells: 4, method: 'METHOD_SIMULTANEOUS', simultaneous: 50, sequential: 1,
  });
  await bare.waitForSelector(`tr[data-job-id="${ignored}"]`);
  await bare.waitForTimeout(1500);  // a poll or more after the new job was listed
  const kept = await bare.textContent('#job-id');
  const hash = await bare.evaluate(() => location.hash);
  check('a job picked by hand stays selected when a newer one appears',
    kept === finished && hash === `#job=${finished}`, `shows ${kept}, URL ${hash}`);
  await fetch(`${url}v1/jobs/${running}:cancel`, { method: 'POST' });

  // 6. The boundary field: a sliding boundary's report shows once the job has succeeded (the
  // demo block is a cube: 4 x 12 feature edges in 12 curves, 8 corners), and kept layers with a
  // free boundary are refused by the server, naming the fields.
  const slid = await submitDemoJob(page, {
    cells: 4, method: 'METHOD_SIMULTANEOUS', simultaneous: 50, sequential: 1,
    boundary: 'BOUNDARY_SLIDE',
  });
  await page.waitForFunction(() => document.getElementById('job-state').textContent === 'SUCCEEDED');
  const boundaryReport = await page.waitForFunction(() => {
    const text = document.getElementById('boundary-report').textContent;
    return text.includes('corners') ? text : null;
  }).then((handle) => handle.jsonValue(), () => '');
  check('a sliding boundary\'s report shows its features', boundaryReport.startsWith('boundary slide') &&
    boundaryReport.includes('48 feature edges in 12 curves') && boundaryReport.includes('8 corners'),
  `job ${slid}: ${boundaryReport}`);
  const slidApi = await (await fetch(`${url}v1/jobs/${slid}`)).json();
  check('the sliding job is listed as succeeded', slidApi.state === 'JOB_STATE_SUCCEEDED', slidApi.state);
  await fillDemoForm(page, {
    cells: 4, method: 'METHOD_SIMULTANEOUS', simultaneous: 50, sequential: 1,
    boundary: 'BOUNDARY_FREE', keepLayers: true,
  });
  await page.click('#demo-submit');
  const refused = await page.waitForFunction(() => {
    const text = document.getElementById('demo-status').textContent;
    return text.includes('INVALID_ARGUMENT') ? text : null;
  }).then((handle) => handle.jsonValue(), () => '');
  check('kept layers with a free boundary are refused, naming the fields',
    refused.includes('keep_layers') && refused.includes('BOUNDARY_FREE'), refused);
  await page.screenshot({ path: path.join(outputDir, 'dashboard-boundary.png'), fullPage: true });
} catch (error) {
  check('browser run', false, error.stack || String(error));
} finally {
  if (context) await context.close();
  server.kill('SIGTERM');
  if (authServer) authServer.kill('SIGTERM');
  fs.rmSync(userDataDir, { recursive: true, force: true });
}
console.log(`browser_dashboard: ${passed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
