// getme dashboard: the job list from GET /v1/jobs (polled), one job's progress from its
// Server-Sent Events (GET /v1/jobs/{id}/events), cancel via POST /v1/jobs/{id}:cancel.
// Without a job in the URL (#job=ID) the page shows the newest job at once and follows newer ones
// as they appear, until the user picks a job (a click, the demo form, or the URL).
// JSON follows protobuf's canonical mapping: lowerCamelCase names, 64-bit integers as strings.
// A server with --auth_tokens_file answers 401 without a bearer token: the page then asks for one
// and keeps it in sessionStorage (this tab only, gone when it closes).
'use strict';

const POLL_MS = 1000;
const SVG = 'http://www.w3.org/2000/svg';
const PHASE_NAMES = {
  PHASE_UNTANGLE: 'untangle', PHASE_SIMULTANEOUS: 'simultaneous', PHASE_SEQUENTIAL: 'sequential',
  PHASE_WARPAGE: 'warpage', PHASE_SMART_LAPLACE: 'smart Laplace', PHASE_LAPLACE: 'Laplace',
  PHASE_POLISH: 'polish', PHASE_LAYERS: 'layers',
};
const BOUNDARY_NAMES = { BOUNDARY_FIXED: 'fixed', BOUNDARY_SLIDE: 'slide', BOUNDARY_FREE: 'free' };
const PHASE_COLOURS = ['#eef3ff', '#fff4e8', '#eefaf0', '#f6eefc'];
const FINAL_STATES = new Set(['SUCCEEDED', 'FAILED', 'CANCELLED']);

const $ = (id) => document.getElementById(id);
const stateName = (state) => (state || '').replace('JOB_STATE_', '');
const methodName = (method) => (method || '').replace('METHOD_', '').toLowerCase();

let jobs = [];
// The selected job: its id, event stream, and chart points {phase, iteration, qMin, qMean}.
let selected = null;
// Whether the user chose the selected job (click, demo form, URL); if not, the page follows the
// newest job.
let pickedByHand = false;
let drawQueued = false;

// ---- Access token ---------------------------------------------------------------------------

const TOKEN_KEY = 'getme-token';
const token = () => sessionStorage.getItem(TOKEN_KEY) || '';

// fetch() with the bearer token, if any; a 401 asks for a (new) token.
async function api(path, options = {}) {
  const headers = { ...(options.headers || {}) };
  if (token()) headers.Authorization = `Bearer ${token()}`;
  const response = await fetch(path, { ...options, headers });
  if (response.status === 401) askForToken();
  return response;
}

function askForToken() {
  $('token-panel').hidden = false;
  $('token-message').textContent = token()
    ? 'The server refused this token: enter another.'
    : 'This server requires an access token.';
}

$('token-form').addEventListener('submit', (event) => {
  event.preventDefault();
  const value = new FormData(event.target).get('token').trim();
  if (!value) return;
  sessionStorage.setItem(TOKEN_KEY, value);
  event.target.reset();
  $('token-panel').hidden = true;
  if (selected) {  // reopen its event stream with the token
    const id = selected.id;
    if (selected.events) selected.events.close();
    selected = null;
    select(id, { byHand: pickedByHand });
  }
});

// EventSource cannot send headers: the token goes in the one query parameter the server accepts
// on event streams (it never logs query strings).
function eventsUrl(id) {
  const base = `/v1/jobs/${id}/events`;
  return token() ? `${base}?access_token=${encodeURIComponent(token())}` : base;
}

// ---- Job list -------------------------------------------------------------------------------

async function pollJobs() {
  try {
    const response = await api('/v1/jobs');
    if (!response.ok) throw new Error(`HTTP ${response.status}`);
    jobs = (await response.json()).jobs || [];
    $('connection').textContent = `${jobs.length} job(s) · updated ${new Date().toLocaleTimeString()}`;
    if (!pickedByHand) followNewest();
    renderJobs();
  } catch (error) {
    $('connection').textContent = `server unreachable (${error.message}); retrying`;
  }
  setTimeout(pollJobs, POLL_MS);
}

// The newest of `list` (newest first, as GET /v1/jobs sends it): the running one if any runs,
// else the most recently created.
const newestOf = (list) => list.find((job) => stateName(job.state) === 'RUNNING') || list[0];

// While the user has not picked a job: with none shown yet, show the newest; later, when jobs
// appear that the previous poll did not list, show the newest of those. A job that has just
// finished thus keeps its chart and histogram until a new job comes.
let listedIds = null;
function followNewest() {
  const fresh = listedIds ? jobs.filter((job) => !listedIds.has(job.jobId)) : [];
  listedIds = new Set(jobs.map((job) => job.jobId));
  const next = newestOf(selected ? fresh : jobs);
  if (next && (!selected || next.jobId !== selected.id)) select(next.jobId, { byHand: false });
}

// The engine does not know in advance how many iterations a phase takes (it stops on a
// tolerance), so progress is told as the phase and its iteration count, not as a percentage.
function progressOf(job) {
  const state = stateName(job.state);
  const latest = job.latestProgress || {};
  if (state === 'QUEUED') return 'waiting for a worker';
  if (!latest.phase || latest.phase === 'PHASE_UNSPECIFIED') return '';
  const phase = PHASE_NAMES[latest.phase] || latest.phase;
  const unit = latest.phase === 'PHASE_SEQUENTIAL' || latest.phase === 'PHASE_WARPAGE' ? 'picks'
    : latest.phase === 'PHASE_POLISH' ? 'sweeps' : latest.phase === 'PHASE_LAYERS' ? 'passes'
      : 'iterations';
  const count = `${phase} · ${Number(latest.iteration).toLocaleString()} ${unit}`;
  return state === 'RUNNING' ? count : `${count} · ${latest.elapsedSeconds.toFixed(1)} s`;
}

function renderJobs() {
  const body = $('jobs').querySelector('tbody');
  body.replaceChildren(...jobs.map((job) => {
    const row = document.createElement('tr');
    row.dataset.jobId = job.jobId;
    if (selected && selected.id === job.jobId) row.classList.add('selected');
    const state = stateName(job.state);
    const latest = job.latestProgress || {};
    row.innerHTML = `<td><code>${job.jobId}</code></td>
      <td><span class="state ${state}">${state}</span></td>
      <td>${methodName(job.method)}</td><td>${Number(job.elements).toLocaleString()}</td>
      <td class="progress">${progressOf(job)}</td>
      <td>${latest.qMin !== undefined && state !== 'QUEUED' ? latest.qMin.toFixed(4) : ''}</td>`;
    row.addEventListener('click', () => select(job.jobId, { byHand: true }));
    return row;
  }));
  $('no-jobs').hidden = jobs.length > 0;
  if (selected) {
    const job = jobs.find((j) => j.jobId === selected.id);
    if (job) {
      showState(stateName(job.state), job);
    } else if (!selected.ended) {
      $('job-summary').textContent = 'This job is no longer known to the server (its record expired).';
    }
  }
}

// ---- Selected job ----------------------------------------------------------------------------

// Shows job `id`. A job picked by hand goes into the URL (#job=ID), so a reload comes back to it;
// a job the page follows by itself does not, so a reload follows the newest again.
function select(id, { byHand = true } = {}) {
  pickedByHand = byHand;
  if (byHand) history.replaceState(null, '', `#job=${id}`);
  else if (location.hash) history.replaceState(null, '', location.pathname + location.search);
  if (selected && selected.id === id) return;
  if (selected && selected.events) selected.events.close();
  selected = { id, points: [], ended: false, events: null };
  $('job-panel').hidden = false;
  $('job-id').textContent = id;
  $('job-summary').textContent = '';
  $('histogram').replaceChildren();
  $('histogram').dataset.ready = 'false';
  $('histogram-note').textContent = 'shown when the job has succeeded';
  $('boundary-report').textContent = '';
  draw();
  renderJobs();
  openEvents(selected);
}

function openEvents(job) {
  // EventSource reconnects by itself after a dropped connection (the server asks for 2 s); the
  // stream then starts again from the job's latest event. Events that arrive while the trace
  // (the run so far) loads wait in `pending`, so no event falls between the two.
  job.pending = [];
  const events = new EventSource(eventsUrl(job.id));
  job.events = events;
  events.addEventListener('progress', (message) => {
    const event = JSON.parse(message.data);
    if (job.pending) job.pending.push(event);
    else addPoint(job, event);
  });
  events.addEventListener('result', (message) => {
    const result = JSON.parse(message.data);
    drawHistogram(result);
    showBoundaryReport(result);
  });
  events.addEventListener('end', (message) => {
    const final = JSON.parse(message.data);
    job.ended = true;
    events.close();
    showState(stateName(final.state), final);
    // The list is polled; do not show this job as running until the next poll.
    jobs = jobs.map((j) => (j.jobId === final.jobId ? final : j));
    renderJobs();
  });
  events.onerror = () => {
    if (events.readyState === EventSource.CLOSED && !job.ended) {
      $('job-summary').textContent = 'Lost the event stream (job unknown or server gone).';
    }
  };
  loadTrace(job);
}

async function loadTrace(job) {
  let trace = [];
  try {
    const response = await api(`/v1/jobs/${job.id}/trace`);
    if (response.ok) trace = (await response.json()).events || [];
  } catch (error) {
    // The stream alone still draws from now on.
  }
  const pending = job.pending;
  job.pending = null;
  for (const event of [...trace, ...pending]) addPoint(job, event);
}

function addPoint(job, event) {
  if (job !== selected || !event.phase || event.phase === 'PHASE_UNSPECIFIED') return;
  const sequence = Number(event.sequence);
  if (sequence <= (job.lastSequence || 0)) return;
  job.lastSequence = sequence;
  // A progress event means a worker has the job; the state poll may not have caught up yet.
  const badge = $('job-state');
  if (badge.textContent === 'QUEUED') {
    badge.textContent = 'RUNNING';
    badge.className = 'state RUNNING';
  }
  const point = {
    phase: event.phase, iteration: Number(event.iteration), qMin: event.qMin, qMean: event.qMean,
  };
  const last = job.points[job.points.length - 1];
  // The final event repeats the latest state: keep one point per state.
  if (last && last.phase === point.phase && last.iteration === point.iteration) return;
  job.points.push(point);
  if (!drawQueued) {
    drawQueued = true;
    requestAnimationFrame(() => { drawQueued = false; draw(); });
  }
}

function showState(state, job) {
  const badge = $('job-state');
  badge.textContent = state;
  badge.className = `state ${state}`;
  $('cancel').disabled = FINAL_STATES.has(state);
  const parts = [`${methodName(job.method)}`, `${Number(job.elements).toLocaleString()} elements`];
  if (job.errorMessage) parts.push(job.errorMessage);
  $('job-summary').textContent = parts.join(' · ');
}

async function cancelSelected() {
  if (!selected) return;
  const response = await api(`/v1/jobs/${selected.id}:cancel`, { method: 'POST' });
  const body = await response.json();
  if (!response.ok) {
    $('job-summary').textContent = `cancel failed: ${body.code}: ${body.message}`;
    return;
  }
  showState(stateName(body.state), body);
}

// ---- Charts ---------------------------------------------------------------------------------

function svgElement(name, attributes, text) {
  const element = document.createElementNS(SVG, name);
  for (const [key, value] of Object.entries(attributes)) element.setAttribute(key, value);
  if (text !== undefined) element.textContent = text;
  return element;
}

// Phases get x-bands as wide as their share of the points; within a band x follows the
// iteration, so both phases stay readable although sequential picks outnumber iterations.
function draw() {
  const chart = $('chart');
  const points = selected ? selected.points : [];
  chart.dataset.points = String(points.length);
  const [width, height, left, right, top, bottom] = [640, 260, 44, 10, 10, 28];
  const plotWidth = width - left - right;
  const plotHeight = height - top - bottom;
  const children = [];
  const phases = [];
  for (const point of points) {
    const phase = phases[phases.length - 1];
    if (!phase || phase.name !== point.phase) phases.push({ name: point.phase, points: [point] });
    else phase.points.push(point);
  }
  const y = (q) => top + plotHeight * (1 - Math.max(0, Math.min(1, q)));
  for (const q of [0, 0.25, 0.5, 0.75, 1]) {
    children.push(svgElement('line', { x1: left, x2: width - right, y1: y(q), y2: y(q), stroke: '#e4e6ee' }));
    children.push(svgElement('text', { x: left - 6, y: y(q) + 4, 'text-anchor': 'end' }, q.toFixed(2)));
  }
  let x0 = left;
  const lines = { qMin: [], qMean: [] };
  phases.forEach((phase, index) => {
    const bandWidth = plotWidth * (phase.points.length / points.length);
    const first = phase.points[0].iteration;
    const span = Math.max(1, phase.points[phase.points.length - 1].iteration - first);
    children.push(svgElement('rect', {
      x: x0, y: top, width: bandWidth, height: plotHeight,
      fill: PHASE_COLOURS[index % PHASE_COLOURS.length], class: 'phase', 'data-phase': phase.name,
    }));
    const label = PHASE_NAMES[phase.name] || phase.name;
    children.push(svgElement('text', { x: x0 + 4, y: height - 8 },
      bandWidth > 160 ? `${label} (${first}…${first + span})` : label));
    if (index > 0) {
      children.push(svgElement('line', { x1: x0, x2: x0, y1: top, y2: top + plotHeight, stroke: '#99a', 'stroke-dasharray': '4 3' }));
    }
    for (const point of phase.points) {
      const x = x0 + bandWidth * ((point.iteration - first) / span);
      lines.qMin.push(`${x.toFixed(1)},${y(point.qMin).toFixed(1)}`);
      lines.qMean.push(`${x.toFixed(1)},${y(point.qMean).toFixed(1)}`);
    }
    x0 += bandWidth;
  });
  children.push(svgElement('polyline', { points: lines.qMean.join(' '), fill: 'none', stroke: '#e4882f', 'stroke-width': 2, class: 'q-mean' }));
  children.push(svgElement('polyline', { points: lines.qMin.join(' '), fill: 'none', stroke: '#2f6fe4', 'stroke-width': 2, class: 'q-min' }));
  if (points.length === 0) {
    children.push(svgElement('text', { x: width / 2, y: height / 2, 'text-anchor': 'middle' }, 'waiting for progress events…'));
  }
  chart.replaceChildren(...children);
}

function drawHistogram(result) {
  const before = (result.before.histogram || []).map(Number);
  const after = (result.after.histogram || []).map(Number);
  const bins = Math.max(before.length, after.length);
  const svg = $('histogram');
  if (bins === 0) return;
  const [width, height, left, bottom, top] = [640, 220, 44, 24, 10];
  const plotHeight = height - top - bottom;
  const peak = Math.max(1, ...before, ...after);
  const binWidth = (width - left - 10) / bins;
  const children = [];
  for (let i = 0; i < bins; ++i) {
    const x = left + i * binWidth;
    for (const [counts, offset, fill, name] of [[before, 0.1, '#b8bcc8', 'before'], [after, 0.5, '#2f6fe4', 'after']]) {
      const barHeight = plotHeight * ((counts[i] || 0) / peak);
      children.push(svgElement('rect', {
        x: x + binWidth * offset, y: top + plotHeight - barHeight, width: binWidth * 0.4, height: barHeight,
        fill, class: `bar-${name}`,
      }, undefined));
    }
    if (i % Math.ceil(bins / 10) === 0) {
      children.push(svgElement('text', { x, y: height - 8 }, (i / bins).toFixed(1)));
    }
  }
  children.push(svgElement('text', { x: left - 6, y: top + 10, 'text-anchor': 'end' }, String(peak)));
  children.push(svgElement('text', { x: width - 12, y: height - 8, 'text-anchor': 'end' }, 'q'));
  svg.replaceChildren(...children);
  svg.dataset.ready = 'true';
  $('histogram-note').textContent =
    `q_min ${result.before.qMin.toFixed(4)} → ${result.after.qMin.toFixed(4)}, ` +
    `q_mean ${result.before.qMean.toFixed(4)} → ${result.after.qMean.toFixed(4)}, ` +
    `${Number(result.iterationsSimultaneous)} simultaneous iterations, ` +
    `${Number(result.iterationsSequential)} sequential picks, ${result.seconds.toFixed(2)} s`;
}

// The boundary the job ran with and, for a sliding boundary or kept layers, what they did (the
// CLI's summary says the same: client/cli/text_reports.cc).
function showBoundaryReport(result) {
  const lines = [`boundary ${BOUNDARY_NAMES[result.boundary] || 'unspecified'}`];
  const slide = result.boundarySlide;
  if (slide && result.boundary === 'BOUNDARY_SLIDE') {
    lines[0] += `: ${Number(slide.slidNodes)} of ${Number(slide.slidingNodes)} sliding nodes moved, ` +
      `at most ${Number(slide.maxDistance.toPrecision(3))} from the input's surface; ` +
      `${Number(slide.featureEdges)} feature edges in ${Number(slide.featureCurves)} curves, ` +
      `${Number(slide.corners)} corners (fixed)`;
  }
  const layers = result.layers;
  if (layers) {
    const height = (name) => `${layers.before[name].toPrecision(4)} → ${layers.after[name].toPrecision(4)}`;
    lines.push(`layers kept: ${Number(layers.columns)} columns of ${Number(layers.columnElements)} ` +
      `elements, ${layers.layers} layers, ${Number(layers.layerNodes)} nodes held at their wall ` +
      `distance; first-layer height min ${height('firstMin')}, mean ${height('firstMean')}, ` +
      `max ${height('firstMax')}; lean ${height('meanLeanDegrees')}°; ` +
      `largest height change ${Number(layers.maxHeightChange.toPrecision(3))}`);
  }
  $('boundary-report').replaceChildren(...lines.map((line) => {
    const item = document.createElement('span');
    item.textContent = line;
    item.className = 'line';
    return item;
  }));
}

// ---- Demo job: a jittered tetrahedral block made here, posted as JSON ----------------------

function demoMesh(cells) {
  let seed = 12345;
  const random = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  const n = cells + 1;
  const node = (i, j, k) => (k * n + j) * n + i;
  const coordinates = [];
  for (let k = 0; k < n; ++k) {
    for (let j = 0; j < n; ++j) {
      for (let i = 0; i < n; ++i) {
        const interior = i > 0 && j > 0 && k > 0 && i < cells && j < cells && k < cells;
        const jitter = () => (interior ? (random() - 0.5) * 0.6 : 0);
        coordinates.push(i + jitter(), j + jitter(), k + jitter());
      }
    }
  }
  const volume = (a, b, c, d) => {
    const p = (v, axis) => coordinates[3 * v + axis];
    const e = [b, c, d].map((v) => [0, 1, 2].map((axis) => p(v, axis) - p(a, axis)));
    return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
      e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
      e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  };
  // Kuhn's split of a cube into 6 tetrahedra around its main diagonal 0–7 (corner bits: x=1,
  // y=2, z=4), each oriented positively.
  const kuhn = [[1, 3], [3, 2], [2, 6], [6, 4], [4, 5], [5, 1]];
  const tetrahedra = [];
  for (let k = 0; k < cells; ++k) {
    for (let j = 0; j < cells; ++j) {
      for (let i = 0; i < cells; ++i) {
        const corner = (bits) => node(i + (bits & 1), j + ((bits >> 1) & 1), k + ((bits >> 2) & 1));
        for (const [a, b] of kuhn) {
          let tet = [corner(0), corner(a), corner(b), corner(7)];
          if (volume(...tet) < 0) tet = [tet[0], tet[2], tet[1], tet[3]];
          tetrahedra.push(...tet);
        }
      }
    }
  }
  return { coordinates, tetrahedra };
}

async function submitDemo(event) {
  event.preventDefault();
  const form = new FormData(event.target);
  const cells = Number(form.get('cells'));
  const body = {
    parameters: {
      method: form.get('method'),
      simultaneousTolerance: 0,
      simultaneousMaxIterations: String(form.get('simultaneous')),
      sequentialMaxIterations: String(form.get('sequential')),
      sequentialStallIterations: String(form.get('sequential')),
      sequentialImprovementTolerance: 0,
      // With the polish on, the substeps would hand on early (quality.md#stop-rules): the demo
      // runs every iteration asked for, so the windows are those of the fields above.
      polish: form.get('polish') === 'on',
      simultaneousHandoffWindow: '0',
      sequentialHandoffWindow: String(form.get('sequential')),
      boundary: form.get('boundary'),
      keepLayers: form.get('keepLayers') === 'on',
    },
    mesh: demoMesh(cells),
  };
  $('demo-status').textContent = 'submitting…';
  const response = await api('/v1/jobs', {
    method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body),
  });
  const reply = await response.json();
  if (!response.ok) {
    $('demo-status').textContent = `${reply.code}: ${reply.message}`;
    return;
  }
  $('demo-status').textContent = `job ${reply.jobId} queued`;
  jobs.unshift(reply);
  select(reply.jobId, { byHand: true });
}

$('cancel').addEventListener('click', cancelSelected);
$('demo-form').addEventListener('submit', submitDemo);
const fromHash = /job=([0-9a-f]+)/.exec(location.hash);
if (fromHash) select(fromHash[1], { byHand: true });
pollJobs();
