// Ramp frame <-> WGS-84, the same transformation as backend/usvstation/geo.py:
// the ramp frame is the local East-North-Up plane at the ramp end, turned so that
// +x points along the ramp bearing (compass, clockwise from north) and +y to its
// left; ENU <-> geodetic goes exactly through ECEF on the WGS-84 ellipsoid.

const A = 6378137.0; // WGS-84 semi-major axis, m
const F = 1 / 298.257223563;
const E2 = F * (2 - F); // first eccentricity squared
const RAD = Math.PI / 180;

export function geodeticToEcef(latDeg, lonDeg, h) {
  const lat = latDeg * RAD;
  const lon = lonDeg * RAD;
  const s = Math.sin(lat);
  const c = Math.cos(lat);
  const n = A / Math.sqrt(1 - E2 * s * s);
  return [(n + h) * c * Math.cos(lon), (n + h) * c * Math.sin(lon), (n * (1 - E2) + h) * s];
}

export function ecefToGeodetic(x, y, z) {
  const lon = Math.atan2(y, x);
  const p = Math.hypot(x, y);
  let lat = Math.atan2(z, p * (1 - E2));
  for (let i = 0; i < 8; i++) {
    const s = Math.sin(lat);
    const n = A / Math.sqrt(1 - E2 * s * s);
    const next = Math.atan2(z + E2 * n * s, p);
    if (Math.abs(next - lat) < 1e-14) {
      lat = next;
      break;
    }
    lat = next;
  }
  const s = Math.sin(lat);
  const h = p * Math.cos(lat) + z * s - A * Math.sqrt(1 - E2 * s * s);
  return [lat / RAD, lon / RAD, h];
}

export function wrapDeg(deg) {
  return ((deg % 360) + 360) % 360;
}

export class RampFrame {
  constructor(lat, lon, rampBearingDeg = 0, height = 0) {
    this.lat = lat;
    this.lon = lon;
    this.rampBearingDeg = rampBearingDeg;
    this.height = height;
    this.origin = geodeticToEcef(lat, lon, height);
    this.sinLat = Math.sin(lat * RAD);
    this.cosLat = Math.cos(lat * RAD);
    this.sinLon = Math.sin(lon * RAD);
    this.cosLon = Math.cos(lon * RAD);
    this.sinB = Math.sin(rampBearingDeg * RAD);
    this.cosB = Math.cos(rampBearingDeg * RAD);
  }

  rampToEnu(x, y) {
    return [x * this.sinB - y * this.cosB, x * this.cosB + y * this.sinB];
  }

  enuToRamp(e, n) {
    return [e * this.sinB + n * this.cosB, -e * this.cosB + n * this.sinB];
  }

  enuToEcef(e, n, u) {
    const { sinLat: sp, cosLat: cp, sinLon: sl, cosLon: cl } = this;
    const [x0, y0, z0] = this.origin;
    return [
      x0 - sl * e - sp * cl * n + cp * cl * u,
      y0 + cl * e - sp * sl * n + cp * sl * u,
      z0 + cp * n + sp * u,
    ];
  }

  ecefToEnu(x, y, z) {
    const { sinLat: sp, cosLat: cp, sinLon: sl, cosLon: cl } = this;
    const dx = x - this.origin[0];
    const dy = y - this.origin[1];
    const dz = z - this.origin[2];
    return [
      -sl * dx + cl * dy,
      -sp * cl * dx - sp * sl * dy + cp * dz,
      cp * cl * dx + cp * sl * dy + sp * dz,
    ];
  }

  /** Ramp (x, y) in metres to [lat, lon] in degrees, on the origin's ellipsoidal height. */
  toLatLon(x, y) {
    const [e, n] = this.rampToEnu(x, y);
    let up = 0;
    let lat = this.lat;
    let lon = this.lon;
    for (let i = 0; i < 4; i++) {
      const [la, lo, h] = ecefToGeodetic(...this.enuToEcef(e, n, up));
      lat = la;
      lon = lo;
      up -= h - this.height;
    }
    return [lat, lon];
  }

  /** WGS-84 (lat, lon) in degrees to ramp [x, y] in metres (on the tangent plane). */
  toRamp(lat, lon) {
    const [e, n] = this.ecefToEnu(...geodeticToEcef(lat, lon, this.height));
    return this.enuToRamp(e, n);
  }

  headingToCompassDeg(headingDeg) {
    return wrapDeg(this.rampBearingDeg - headingDeg);
  }

  compassToHeadingDeg(compassDeg) {
    return wrapDeg(this.rampBearingDeg - compassDeg);
  }
}
