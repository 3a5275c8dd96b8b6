// Re-plans the mate can act on (issue 25): the station's re-plans (GET /api/replans, then
// {"type": "replan"} events). A proposed one (`--replan confirm`) is drawn beside the running
// plan, with what it changes (predicted clearance gained, arrival later or earlier), and
// Accept / Reject in the command bar (keys y and k; the operator's token); under `auto` the
// card says what was swapped and why. Every re-plan is listed with its outcome.

import { getAlert } from './alerts.js';
import * as api from './api.js';
import { on, state, ui } from './store.js';
import { $, fmt, showError } from './util.js';

const replans = new Map(); // id -> record
const plans = new Map(); // plan id -> plan job (proposals' plans)
const reasons = { get: (alertId) => getAlert(alertId)?.message ?? null };
let policy = null;
let busy = false;

function time(iso) {
  return new Date(iso).toLocaleTimeString([], { hour12: false });
}

/** The newest proposal awaiting the operator, if any. */
export function proposal() {
  return [...replans.values()].filter((r) => r.state === 'proposed')
    .sort((a, b) => b.created_at.localeCompare(a.created_at))[0] ?? null;
}

/** What a proposal changes against the running plan: [clearance now, clearance of the
 * re-plan, arrival delay s] (null where unknown). */
export function changes(record, job, monitor, running, telemetry) {
  const metrics = job?.plan?.metrics;
  const now = monitor?.min_clearance_m ?? null;
  const after = metrics?.min_clearance_m ?? null;
  let delay = null;
  const duration = running?.plan?.metrics?.duration_s;
  if (metrics && duration != null && monitor && telemetry && record.swap_at_ms != null) {
    const etaNow = telemetry.boat_time + (duration - monitor.plan_time_s);
    const etaNew = record.swap_at_ms / 1000 + metrics.duration_s;
    delay = etaNew - etaNow;
  }
  return [now, after, delay];
}

function describe(record) {
  const why = reasons.get(record.alert_id);
  const job = plans.get(record.plan_id);
  const [now, after, delay] = changes(record, job, state.monitor, state.plan, state.telemetry);
  const parts = [`Re-plan proposed${why ? ` (${why})` : ''}:`];
  if (after != null) {
    parts.push(`predicted clearance ${now == null ? '–' : fmt(now, 1)} m → ${fmt(after, 1)} m`
      + (now != null ? ` (${after - now >= 0 ? '+' : ''}${fmt(after - now, 1)} m)` : ''));
  }
  if (delay != null) {
    parts.push(`arrival ${Math.abs(delay) < 0.05 ? 'unchanged' : `${fmt(Math.abs(delay), 1)} s `
      + `${delay > 0 ? 'later' : 'earlier'}`}`);
  }
  if (record.dropped_targets?.length) parts.push(`left out: ${record.dropped_targets.join(', ')}`);
  return parts.join(' ');
}

function outcome(r) {
  const why = reasons.get(r.alert_id);
  const bits = [`${time(r.created_at)} ${r.state}`];
  if (why) bits.push(`for ${why}`);
  if (r.state === 'applied') {
    bits.push(`swapped onto the boat${r.latency_ms != null ? ` in ${fmt(r.latency_ms, 0)} ms`
      : ''} (mission ${r.mission_id})`);
  }
  if (r.error) bits.push(r.error);
  return bits.join(': ');
}

async function render() {
  const current = proposal();
  const box = $('replan-proposal');
  if (current) {
    if (!plans.has(current.plan_id) && current.plan_id) {
      try {
        plans.set(current.plan_id, await api.get(`/api/plans/${current.plan_id}`));
      } catch {
        // the text says less; Accept still works
      }
    }
    if (proposal() !== current) return; // it changed meanwhile: the next render shows it
    $('replan-text').textContent = describe(current);
    ui.map.setProposedPlan(plans.get(current.plan_id)?.plan ?? null);
    box.hidden = false;
    box.dataset.id = current.id;
  } else {
    box.hidden = true;
    box.dataset.id = '';
    ui.map.setProposedPlan(null);
  }
  $('replan-policy').textContent = policy ? `policy: ${policy}` : '';
  const list = [...replans.values()].sort((a, b) => b.created_at.localeCompare(a.created_at));
  const last = list.find((r) => r.state === 'applied' && r.policy === 'auto');
  $('replan-detail').textContent = last ? `Swapped at ${time(last.created_at)}: `
    + `${reasons.get(last.alert_id) ?? 'a warning'}` : '';
  $('replan-rows').replaceChildren(...list.slice(0, 50).map((r) => {
    const li = document.createElement('li');
    li.dataset.id = r.id;
    li.dataset.state = r.state;
    li.textContent = outcome(r);
    return li;
  }));
}

function received(record) {
  replans.set(record.id, record);
  render();
}

async function act(verb) {
  const current = proposal();
  if (!current || busy) return;
  busy = true;
  showError('replan', null);
  $('replan-accept').disabled = true;
  $('replan-reject').disabled = true;
  try {
    received(await api.post(`/api/replans/${current.id}/${verb}`));
  } catch (err) {
    showError('replan', err);
    $('command-error').textContent = `re-plan: ${err.message ?? err}`;
  } finally {
    busy = false;
    $('replan-accept').disabled = false;
    $('replan-reject').disabled = false;
  }
}

export const acceptReplan = () => act('confirm');
export const rejectReplan = () => act('reject');

export async function loadReplans() {
  try {
    const [monitor, list] = await Promise.all([api.get('/api/monitor'), api.get('/api/replans')]);
    policy = monitor.policy;
    for (const r of list) replans.set(r.id, r);
  } catch (err) {
    if (err.status !== 404) showError('replan', err);
  }
  render();
}

export function bindReplans() {
  on('live:replan', received);
  on('live:monitor', () => {
    if (proposal()) render();
  });
  $('replan-accept').addEventListener('click', acceptReplan);
  $('replan-reject').addEventListener('click', rejectReplan);
}
