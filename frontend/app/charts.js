// Telemetry charts after paper 000 Figs. 19 and 20: heading against x and speed
// against time, planned (from the plan's waypoints) and real (from telemetry).
// uPlot in xy mode (mode 2): each series has its own x values, in time order.

import uPlot from 'uplot';

const PLANNED = '#2b6cb0';
const REAL = '#c53030';

/** Auto range with a margin; `empty` until there is data. */
function padded(empty) {
  return (u, min, max) => {
    if (min == null || max == null || !Number.isFinite(min)) return empty;
    const pad = Math.max((max - min) * 0.05, 0.5);
    return [min - pad, max + pad];
  };
}

function xyChart(el, { xLabel, yLabel, xDir = 1, xRange, yRange }) {
  const series = (label, stroke, dash) => ({
    label, stroke, width: 2, dash, points: { show: false }, paths: uPlot.paths.linear(),
  });
  const opts = {
    mode: 2,
    width: Math.max(el.clientWidth, 200),
    height: Math.max(el.clientHeight - 30, 120),
    legend: { live: false },
    cursor: { drag: { x: false, y: false, setScale: false } },
    scales: { x: { time: false, dir: xDir, range: padded(xRange) },
      y: { range: padded(yRange) } },
    axes: [
      { label: xLabel, labelSize: 16, size: 36, stroke: '#2d3748', grid: { stroke: '#e2e8f0' } },
      { label: yLabel, labelSize: 16, size: 52, stroke: '#2d3748', grid: { stroke: '#e2e8f0' } },
    ],
    series: [{}, series('planned', PLANNED, [6, 4]), series('real', REAL)],
  };
  const chart = new uPlot(opts, [null, [[], []], [[], []]], el);
  new ResizeObserver(() => {
    chart.setSize({ width: Math.max(el.clientWidth, 200),
      height: Math.max(el.clientHeight - 30, 120) });
  }).observe(el);
  return chart;
}

export class TelemetryCharts {
  constructor(headingEl, speedEl) {
    this.heading = xyChart(headingEl, { xLabel: 'x (m), ramp end at the right',
      yLabel: 'heading (°, ramp frame)', xDir: -1, xRange: [0, 100], yRange: [120, 240] });
    this.speed = xyChart(speedEl, { xLabel: 't (s) since start', yLabel: 'speed (m/s)',
      xRange: [0, 60], yRange: [0, 3] });
    this.planned = { hx: [], hy: [], st: [], sv: [] };
    this.motion = null; // the moving ramp: {vx, vy} (ramp axes, m/s) and its frame
    this.clearReal();
  }

  /** Under way the plan's speeds are relative to the ramp: so is the real speed drawn, the
   * speed over ground less the ramp's velocity (`ramp` of GET /api/world, in `frame`). */
  setRampMotion(ramp, frame) {
    this.motion = ramp && ramp.source === 'own_ship' ? { vx: ramp.vx, vy: ramp.vy, frame } : null;
  }

  relativeSpeed(r) {
    const m = this.motion;
    if (!m || r.speed == null || r.course_deg == null) return r.speed;
    const c = (r.course_deg * Math.PI) / 180;
    const [vx, vy] = m.frame.enuToRamp(r.speed * Math.sin(c), r.speed * Math.cos(c));
    return Math.hypot(vx - m.vx, vy - m.vy);
  }

  /** Planned heading is the leg's heading, so it steps at each waypoint. */
  setPlan(plan) {
    const p = { hx: [], hy: [], st: [], sv: [] };
    const wps = plan ? plan.waypoints : [];
    wps.forEach((w, i) => {
      p.hx.push(w.x);
      p.hy.push(w.heading_deg);
      const next = wps[i + 1];
      if (next) {
        p.hx.push(next.x);
        p.hy.push(w.heading_deg);
      }
      p.st.push(w.t);
      p.sv.push(w.speed);
    });
    this.planned = p;
    this.dirty = true;
  }

  clearReal() {
    this.real = { hx: [], hy: [], st: [], sv: [] };
    this.t0 = null;
    this.dirty = true;
  }

  /** Telemetry rows of the shown run; t counts from the run's first row. */
  appendReal(rows) {
    for (const r of rows) {
      if (this.t0 === null) this.t0 = r.boat_time;
      if (r.x != null && r.ramp_heading_deg != null) {
        this.real.hx.push(r.x);
        this.real.hy.push(r.ramp_heading_deg);
      }
      this.real.st.push(r.boat_time - this.t0);
      this.real.sv.push(this.relativeSpeed(r));
    }
    this.dirty = rows.length > 0 || this.dirty;
  }

  /** Redraw when something changed since the last call. */
  flush() {
    if (!this.dirty) return;
    this.dirty = false;
    const p = this.planned;
    const r = this.real;
    this.heading.setData([null, [p.hx, p.hy], [r.hx, r.hy]]);
    this.speed.setData([null, [p.st, p.sv], [r.st, r.sv]]);
  }
}
