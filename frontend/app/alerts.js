// Alerts for a bridge (IEC 62923 / MSC.302(87) alert management, issue 25): the station's
// alerts (GET /api/alerts, then {"type": "alert"} on the websocket), one per cause, each
// changed in place and `active` until its condition ends.
//
// - The alert bar under the header always shows the highest active alert (alarm, warning,
//   caution, advisory; unacknowledged before acknowledged, then the newest) in a
//   role="alert" region, with Silence and Acknowledge; it never scrolls away.
// - Sound: a warning or alarm that the station announces (new, or risen) beeps; while it
//   stays active and unacknowledged it beeps again every REPEAT_MS. Silence stops the sound
//   of that alert until the station announces it again; acknowledging is separate (and is
//   recorded by the station).
// - The History lists every alert with its state; "Acknowledge all" acknowledges them.
// The console adds one alert of its own: the station unreachable (no websocket), which the
// station cannot say.

import * as api from './api.js';
import { emit, on } from './store.js';
import { settings } from './settings.js';
import { $ } from './util.js';

export const RANK = { advisory: 0, caution: 1, warning: 2, alarm: 3 };
const SOUNDED = new Set(['warning', 'alarm']);
const alerts = new Map(); // id -> alert
const silenced = new Map(); // id -> announced_at when silenced
const beeped = new Map(); // id -> announced_at last sounded
let repeatMs = 30000;
let repeatTimer = null;
let localId = 0;
let audio = null;
export const sound = { count: 0 }; // beeps so far (tests read it)

function beep() {
  sound.count += 1;
  if (!settings.sound) return;
  try {
    audio = audio ?? new AudioContext();
    const osc = audio.createOscillator();
    const gain = audio.createGain();
    osc.frequency.value = 880;
    gain.gain.value = 0.15;
    osc.connect(gain).connect(audio.destination);
    osc.start();
    osc.stop(audio.currentTime + 0.35);
  } catch {
    // no audio device: the bar still shows the warning
  }
}

function time(iso) {
  return new Date(iso).toLocaleTimeString([], { hour12: false });
}

const isActive = (a) => a.active !== false;
const isSilenced = (a) => silenced.get(a.id) === (a.announced_at ?? a.time);

/** Active alerts, highest first: priority, unacknowledged first, then the newest. */
export function activeAlerts() {
  return [...alerts.values()].filter(isActive).sort((a, b) => RANK[b.level] - RANK[a.level]
    || Number(a.acknowledged) - Number(b.acknowledged)
    || (b.updated_at ?? b.time).localeCompare(a.updated_at ?? a.time));
}

/** The alert with this id, if the console knows it. */
export function getAlert(id) {
  return alerts.get(id) ?? null;
}

/** Ids of targets with an active, unacknowledged alert (the map flashes them). */
export function unacknowledgedTargets() {
  return new Set(activeAlerts().filter((a) => a.target_id && !a.acknowledged)
    .map((a) => a.target_id));
}

function renderBar() {
  const active = activeAlerts();
  const top = active[0];
  const now = $('alert-now');
  const bar = $('alert-bar');
  bar.className = `alert-bar${top ? ` level-${top.level}` : ''}${top && !top.acknowledged
    ? ' unacked' : ''}`;
  now.className = `alert-now${top ? ` level-${top.level}` : ''}${top?.acknowledged ? ' acked'
    : ''}`;
  now.textContent = top ? `${top.level.toUpperCase()}: ${top.message}`
    + `${top.acknowledged ? ' (acknowledged)' : ''}` : '';
  now.dataset.id = top?.id ?? '';
  $('alert-none').hidden = Boolean(top);
  $('alert-more').textContent = active.length > 1 ? `+${active.length - 1} more active` : '';
  $('alert-bar-ack').hidden = !top || top.acknowledged;
  const audible = top && SOUNDED.has(top.level) && !top.acknowledged;
  $('alert-bar-silence').hidden = !audible || isSilenced(top);
}

function renderList() {
  const all = [...alerts.values()].sort((a, b) => b.time.localeCompare(a.time));
  $('alerts-count').textContent = `${all.filter(isActive).length} active, `
    + `${all.filter((a) => !a.acknowledged).length} unacknowledged`;
  $('alerts-ack-all').disabled = !all.some((a) => !a.acknowledged);
  const list = $('alerts-list');
  list.replaceChildren(...all.slice(0, 100).map((a) => {
    const li = document.createElement('li');
    li.className = `level-${a.level}${a.acknowledged ? ' acked' : ''}${isActive(a) ? ''
      : ' ended'}`;
    li.dataset.kind = a.kind;
    li.dataset.id = a.id;
    const state = isActive(a) ? 'active' : `ended ${time(a.ended_at ?? a.updated_at ?? a.time)}`;
    li.textContent = `${time(a.time)} ${a.level}: ${a.message} (${state})`;
    if (!a.acknowledged) {
      const ack = document.createElement('button');
      ack.type = 'button';
      ack.className = 'icon';
      ack.textContent = 'Ack';
      ack.setAttribute('aria-label', `acknowledge: ${a.message}`);
      ack.addEventListener('click', () => acknowledge(a));
      li.append(' ', ack);
    }
    return li;
  }));
}

function render() {
  renderBar();
  renderList();
  emit('alerts', activeAlerts());
}

async function acknowledge(alert) {
  if (alert.local) { // the console's own: the station has no record of it
    alert.acknowledged = true;
    render();
    return;
  }
  try {
    alerts.set(alert.id, await api.post(`/api/alerts/${alert.id}/ack`));
  } catch (err) {
    $('alert-more').textContent = `cannot acknowledge: ${err.message}`;
    return;
  }
  render();
}

function silence(alert) {
  silenced.set(alert.id, alert.announced_at ?? alert.time);
  render();
}

/** Sound an alert the station announced now (new, or risen) unless silenced or known. */
function received(alert, { fresh }) {
  alerts.set(alert.id, alert);
  const announced = alert.announced_at ?? alert.time;
  if (fresh && isActive(alert) && SOUNDED.has(alert.level) && !alert.acknowledged
      && beeped.get(alert.id) !== announced && !isSilenced(alert)) {
    beeped.set(alert.id, announced);
    beep();
  } else if (!fresh) {
    beeped.set(alert.id, announced);
  }
  render();
}

/** Every REPEAT_MS: one beep while a warning or alarm is active, unacknowledged, not silenced. */
function repeatSound() {
  if (activeAlerts().some((a) => SOUNDED.has(a.level) && !a.acknowledged && !isSilenced(a))) {
    beep();
  }
}

/** The repeat interval (30 s); tests shorten it. */
export function setRepeatMs(ms) {
  repeatMs = ms;
  clearInterval(repeatTimer);
  repeatTimer = setInterval(repeatSound, repeatMs);
}

/** An alert raised by the console itself (the station unreachable). */
export function localAlert(level, kind, message) {
  localId += 1;
  const t = new Date().toISOString();
  received({ id: `local-${localId}`, time: t, updated_at: t, announced_at: t, level, kind,
    message, target_id: null, run_id: null, acknowledged: false, active: true, local: true },
  { fresh: true });
}

/** End the console's own alerts of `kind` (the station is back). */
export function clearLocal(kind) {
  for (const a of alerts.values()) {
    if (a.local && a.kind === kind) {
      a.active = false;
      a.ended_at = new Date().toISOString();
    }
  }
  render();
}

export async function loadAlerts() {
  try {
    for (const a of await api.get('/api/alerts')) received(a, { fresh: false });
  } catch (err) {
    if (err.status !== 404) $('alert-more').textContent = `alerts unavailable: ${err.message}`;
  }
}

export function bindAlerts() {
  on('live:alert', (a) => received(a, { fresh: true }));
  $('alerts-ack-all').addEventListener('click', () => {
    for (const a of alerts.values()) if (!a.acknowledged) acknowledge(a);
  });
  $('alerts-history').addEventListener('click', (e) => {
    const list = $('alerts-list');
    list.hidden = !list.hidden;
    e.target.setAttribute('aria-expanded', String(!list.hidden));
  });
  $('alert-bar-ack').addEventListener('click', () => {
    const top = activeAlerts()[0];
    if (top) acknowledge(top);
  });
  $('alert-bar-silence').addEventListener('click', () => {
    const top = activeAlerts()[0];
    if (top) silence(top);
  });
  setRepeatMs(repeatMs);
  render();
}
