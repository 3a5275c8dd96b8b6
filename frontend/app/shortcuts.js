// Keyboard shortcuts, listed on `?`. HOLD and RESUME act at once; START and ABORT
// always ask first; y and k accept or reject a proposed re-plan. None fires while typing
// in a field.

import { command, confirmAbort } from './mission.js';
import { runPlan } from './plan.js';
import { nextPalette, setSetting, settings } from './settings.js';
import { acceptReplan, rejectReplan } from './replans.js';
import { $ } from './util.js';

export const SHORTCUTS = [
  ['h', 'Hold: the boat holds station (at once)', () => command('hold')],
  ['r', 'Resume the mission (at once)', () => command('resume')],
  ['s', 'Start the mission… (asks first)', () => confirmStart()],
  ['a', 'Abort… (asks first)', () => confirmAbort()],
  ['p', 'Plan', () => runPlan()],
  ['y', 'Accept the proposed re-plan', () => acceptReplan()],
  ['k', 'Keep the running plan: reject the proposed re-plan', () => rejectReplan()],
  ['n', 'Palette: day, dusk, night', () => setSetting('palette', nextPalette())],
  ['l', 'Large text on/off', () => setSetting('large', !settings.large)],
  ['u', 'Speed in m/s or knots', () => setSetting('units', settings.units === 'kn' ? 'ms' : 'kn')],
  ['m', 'Centre the map on the boat', () => $('map').dispatchEvent(new CustomEvent('centre-boat'))],
  ['?', 'This list', () => $('help-dialog').showModal()],
];

export function confirmStart() {
  const dialog = $('start-dialog');
  dialog.returnValue = '';
  dialog.showModal();
}

function typing(target) {
  return target instanceof HTMLElement && (target.isContentEditable
    || ['INPUT', 'TEXTAREA', 'SELECT'].includes(target.tagName));
}

export function bindShortcuts() {
  const list = $('shortcut-list');
  list.replaceChildren(...SHORTCUTS.map(([key, text]) => {
    const div = document.createElement('div');
    const dt = document.createElement('dt');
    const kbd = document.createElement('kbd');
    kbd.textContent = key;
    dt.append(kbd);
    const dd = document.createElement('dd');
    dd.textContent = text;
    div.append(dt, dd);
    return div;
  }));
  $('start-dialog').addEventListener('close', () => {
    if ($('start-dialog').returnValue === 'start') command('start');
  });
  document.addEventListener('keydown', (e) => {
    if (e.ctrlKey || e.metaKey || e.altKey || typing(e.target)) return;
    if (document.querySelector('dialog[open]')) return;
    const hit = SHORTCUTS.find(([key]) => key === e.key.toLowerCase() || key === e.key);
    if (!hit) return;
    e.preventDefault();
    hit[2]();
  });
  $('help-button').addEventListener('click', () => $('help-dialog').showModal());
}
