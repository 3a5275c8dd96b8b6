// Mission and commands: upload the plan to the boat with per-waypoint progress,
// and the boat commands (ABORT asks first).

import * as api from './api.js';
import { updateStale } from './plan.js';
import { setFollow } from './render.js';
import { state } from './store.js';
import { $, showError, sleep } from './util.js';

export function renderMission(mission) {
  state.mission = mission;
  if (!mission) return;
  const { sent, acked, total } = mission.progress;
  $('mission-state').textContent = `mission ${mission.id}: ${mission.state}`;
  $('upload-progress').hidden = false;
  $('upload-bar').max = Math.max(total, 1);
  $('upload-bar').value = acked;
  $('upload-text').textContent = `${acked} of ${total} waypoints acknowledged (${sent} sent)`;
  const list = $('upload-items');
  if (list.children.length !== total) {
    list.replaceChildren(...Array.from({ length: total }, (_, i) => {
      const li = document.createElement('li');
      li.textContent = String(i);
      return li;
    }));
  }
  [...list.children].forEach((li, i) => {
    const status = i < acked ? 'acked' : i < sent ? 'sent' : 'waiting';
    li.className = status;
    li.title = `waypoint ${i}: ${status}`;
  });
  if (mission.state === 'failed' && mission.error) showError('upload', new Error(mission.error));
}

async function upload() {
  showError('upload', null);
  const button = $('upload');
  button.disabled = true;
  try {
    let mission = await api.post('/api/missions', { plan_id: state.plan.id });
    renderMission(mission);
    while (mission.state === 'uploading') {
      await sleep(200);
      mission = await api.get(`/api/missions/${mission.id}`);
      if (!state.mission || state.mission.id === mission.id) renderMission(mission);
    }
  } catch (err) {
    showError('upload', err);
  } finally {
    updateStale();
  }
}

export async function command(name) {
  showError('command', null);
  $('command-result').textContent = '';
  const buttons = document.querySelectorAll('[data-command]');
  buttons.forEach((b) => { b.disabled = true; });
  try {
    const body = { command: name };
    if (name === 'start' && state.mission) body.mission_id = state.mission.id; // START names it
    const r = await api.post('/api/boat/command', body);
    $('command-result').textContent = `${name.toUpperCase()}: ${r.result}, boat ${r.state ?? '–'}`;
    if (name === 'start') setFollow(true);
  } catch (err) {
    showError('command', err);
  } finally {
    buttons.forEach((b) => { b.disabled = false; });
  }
}

/** Ask before ABORT: the boat stops at once and the run ends. */
export function confirmAbort() {
  const dialog = $('abort-dialog');
  dialog.returnValue = '';
  dialog.showModal();
}

export function bindMissionControls() {
  $('upload').addEventListener('click', upload);
  for (const b of document.querySelectorAll('[data-command]')) {
    if (b.dataset.command === 'abort' || b.dataset.command === 'start') continue;
    b.addEventListener('click', () => command(b.dataset.command));
  }
  const dialog = $('abort-dialog');
  $('cmd-abort').addEventListener('click', confirmAbort);
  $('cmd-start').addEventListener('click', () => {
    const start = $('start-dialog');
    start.returnValue = '';
    start.showModal();
  });
  dialog.addEventListener('close', () => {
    if (dialog.returnValue === 'abort') command('abort');
  });
}
