/*
 * usv_boat_host: the C boat on a pty/serial device or a TCP port, with a kinematic
 * vehicle that the boat's thrust commands drive (POSIX host build).
 *
 *   usv_boat_host DEVICE|PORT|pty (--link-key PATH | --insecure-link) [--boat-id N]
 *       [--station-id N] [--speedup X] [--lat DEG --lon DEG --heading-deg DEG]
 *       [--telemetry-hz HZ] [--start-radius M] [--link-timeout-s S] [--duration S]
 *       [--nv-file PATH] [--baud BPS] [--sensors exact|rtk|gnss|rtk-moving-base] [--seed N]
 *
 * A PORT (digits) listens on 127.0.0.1:PORT (0: any free port) for one client at a time,
 * e.g. `usv-station serve --link socket://127.0.0.1:PORT`; `pty` creates a pseudo-terminal
 * and prints its device (the station opens it); anything else is opened as a serial
 * device or pty slave (raw). --nv-file is the boat's non-volatile memory: the signing
 * floor (the newest signing timestamp seen), written every second and read at boot, so a
 * frame recorded before a reboot is refused after it even without a clock; by default it
 * is KEY.boatN.floor beside the --link-key file (the Python boats' name), created on first
 * use; a clean stop writes it exact ("sign_floor N exact": the next boot accepts from N+1,
 * else from N + 2 s, the frames of the last second before a crash included). --baud paces
 * the boat's telemetry to that line rate behind its replies (0, the default: no pacing). The boat clock runs --speedup times the wall clock;
 * the link timeouts (failsafe, duplicate memory, staging expiry) stay in wall time.
 * The "UART interrupt" is the read() of the main loop: bytes go to usv_boat_rx_byte(),
 * usv_boat_poll() parses them afterwards, as on the microcontroller.
 *
 * Sensors, not truth: the boat gets its navigation from a sensor model (--sensors, default
 * rtk; seeded by --seed), never the vehicle's true state, as backend/usvstation/sim/
 * sensors.py: GNSS fixes at a rate, a latency old and dead-reckoned between them and
 * through outages, with white noise and a Gauss-Markov wander (rtk 0.02 m, gnss 1.5 m
 * CEP); compass bias, noise and lag; gyro bias and noise. The host has no moving ramp, so
 * rtk-moving-base (relative to the ramp) measures like rtk here.
 */
#define _XOPEN_SOURCE 600
#define _DEFAULT_SOURCE

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <arpa/inet.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include "usv_boat.h"

#define PI_D 3.14159265358979323846
#define EARTH_R 6378137.0

typedef struct {
    double north, east;   /* metres from the start point */
    double lat0, lon0;    /* start point, degrees */
    double heading;       /* compass, rad */
    double speed;         /* m/s along the heading */
    double yaw_rate;
    double max_speed;     /* at full thrust */
    double max_yaw_rate;  /* at full differential thrust */
    double tau;           /* speed time constant, s */
    int16_t left, right;  /* per mille */
} vehicle_t;

/* ---- the sensor model (see the header comment) */
typedef struct {
    double white_m, bias_m, bias_tau_s, vel_mps, rate_hz, latency_s, drop_per_min, drop_s;
    double compass_noise_rad, compass_lag_s, gyro_bias, gyro_noise;
    uint8_t fix_type, satellites;
} sensor_spec_t;

typedef struct {
    double t, north, east, vn, ve; /* a fix: when taken, where, how fast */
} fix_t;

#define FIX_QUEUE 16
typedef struct {
    sensor_spec_t spec;
    uint64_t rng;
    double bias_n, bias_e;
    fix_t queue[FIX_QUEUE];
    int head, len;
    fix_t latest;
    int have_latest;
    double next_fix, outage_until, heading, last_t;
    int have_heading;
} sensors_t;

typedef struct {
    int fd;                /* the link: device or accepted client; -1 none */
    double speedup;
    struct timespec start;
    vehicle_t veh;
    sensors_t sens;
    unsigned long sent_bytes;
} host_t;

static volatile sig_atomic_t stop_flag = 0;

static void on_signal(int sig)
{
    (void)sig;
    stop_flag = 1;
}

static double wall_s(const host_t *h)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)(t.tv_sec - h->start.tv_sec) + (double)(t.tv_nsec - h->start.tv_nsec) * 1e-9;
}

/* ---- HAL */
static void hal_send(void *ctx, const uint8_t *buf, uint16_t len)
{
    host_t *h = ctx;
    size_t off = 0;
    if (h->fd < 0) {
        return; /* nobody listening: the bytes go into the air */
    }
    while (off < len) {
        ssize_t n = write(h->fd, buf + off, len - off);
        if (n > 0) {
            off += (size_t)n;
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else {
            return; /* full or gone: dropped, as a UART without a listener */
        }
    }
    h->sent_bytes += len;
}

static uint32_t hal_now_ms(void *ctx)
{
    host_t *h = ctx;
    return (uint32_t)(uint64_t)(wall_s(h) * h->speedup * 1000.0);
}

static void hal_actuate(void *ctx, int16_t left, int16_t right)
{
    host_t *h = ctx;
    h->veh.left = left;
    h->veh.right = right;
}

/* ---- the kinematic vehicle: speed follows the mean thrust (first order), yaw rate the
 * differential thrust (left ahead of right turns clockwise). */
static void vehicle_step(vehicle_t *v, double dt)
{
    double target = (v->left + v->right) / 2000.0 * v->max_speed;
    v->yaw_rate = (v->left - v->right) / 2000.0 * v->max_yaw_rate;
    v->speed += (target - v->speed) * (1.0 - exp(-dt / v->tau));
    v->heading = fmod(v->heading + v->yaw_rate * dt + 4.0 * PI_D, 2.0 * PI_D);
    v->north += v->speed * cos(v->heading) * dt;
    v->east += v->speed * sin(v->heading) * dt;
}

static int sensor_spec(const char *name, sensor_spec_t *s)
{
    memset(s, 0, sizeof *s);
    s->bias_tau_s = 120.0;
    s->fix_type = 3;
    s->satellites = 12;
    if (strcmp(name, "exact") == 0) {
        return 0;
    }
    s->compass_noise_rad = 0.5 * PI_D / 180.0;
    s->compass_lag_s = 0.2;
    s->gyro_bias = 0.05 * PI_D / 180.0;
    s->gyro_noise = 0.1 * PI_D / 180.0;
    if (strcmp(name, "rtk") == 0 || strcmp(name, "rtk-moving-base") == 0) {
        s->white_m = 0.02, s->bias_m = 0.005, s->bias_tau_s = 300.0, s->vel_mps = 0.03;
        s->rate_hz = 10.0, s->latency_s = 0.05, s->drop_per_min = 0.1, s->drop_s = 1.0;
        s->fix_type = 6, s->satellites = 16;
        return 0;
    }
    if (strcmp(name, "gnss") == 0) {
        s->white_m = 0.4, s->bias_m = 1.2, s->bias_tau_s = 120.0, s->vel_mps = 0.1;
        s->rate_hz = 5.0, s->latency_s = 0.1, s->drop_per_min = 0.2, s->drop_s = 2.0;
        s->fix_type = 3, s->satellites = 10;
        return 0;
    }
    return -1;
}

static double rng_uniform(sensors_t *z) /* xorshift64*, in (0, 1) */
{
    z->rng ^= z->rng >> 12;
    z->rng ^= z->rng << 25;
    z->rng ^= z->rng >> 27;
    return ((double)((z->rng * 2685821657736338717ull) >> 11) + 0.5) / 9007199254740992.0;
}

static double rng_normal(sensors_t *z, double std)
{
    double u = rng_uniform(z), v = rng_uniform(z);
    return std > 0.0 ? std * sqrt(-2.0 * log(u)) * cos(2.0 * PI_D * v) : 0.0;
}

static void sensors_init(sensors_t *z, const sensor_spec_t *spec, uint64_t seed)
{
    memset(z, 0, sizeof *z);
    z->spec = *spec;
    z->rng = seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull;
    if (z->rng == 0) {
        z->rng = 1;
    }
    z->bias_n = rng_normal(z, spec->bias_m);
    z->bias_e = rng_normal(z, spec->bias_m);
    z->next_fix = -1e300;
    z->outage_until = -1e300;
}

static double wrap_2pi(double a)
{
    a = fmod(a, 2.0 * PI_D);
    return a < 0.0 ? a + 2.0 * PI_D : a;
}

/* the boat's navigation solution at boat time t from the vehicle's true state */
static void sensors_nav(sensors_t *z, const vehicle_t *v, double t, usv_nav_t *nav)
{
    const sensor_spec_t *s = &z->spec;
    double dt = z->have_latest ? t - z->last_t : 0.0, age, north, east, lat, lon, sog, d;
    double vn = v->speed * cos(v->heading), ve = v->speed * sin(v->heading);
    int ok;
    if (dt < 0.0) {
        dt = 0.0;
    }
    z->last_t = t;
    if (s->bias_m > 0.0 && dt > 0.0) {
        double a = exp(-dt / s->bias_tau_s), w = s->bias_m * sqrt(1.0 - a * a);
        z->bias_n = a * z->bias_n + rng_normal(z, w);
        z->bias_e = a * z->bias_e + rng_normal(z, w);
    }
    if (s->drop_per_min > 0.0 && dt > 0.0 && t >= z->outage_until &&
        rng_uniform(z) < 1.0 - exp(-s->drop_per_min / 60.0 * dt)) {
        z->outage_until = t - s->drop_s * log(rng_uniform(z));
    }
    ok = t >= z->outage_until;
    if (t >= z->next_fix && (ok || !z->have_latest)) {
        fix_t f;
        f.t = t;
        f.north = v->north + z->bias_n + rng_normal(z, s->white_m);
        f.east = v->east + z->bias_e + rng_normal(z, s->white_m);
        f.vn = vn + rng_normal(z, s->vel_mps);
        f.ve = ve + rng_normal(z, s->vel_mps);
        if (!z->have_latest) {
            z->latest = f, z->have_latest = 1;
        }
        if (z->len == FIX_QUEUE) { /* a full queue drops its oldest */
            z->head = (z->head + 1) % FIX_QUEUE, z->len--;
        }
        z->queue[(z->head + z->len) % FIX_QUEUE] = f, z->len++;
        z->next_fix = s->rate_hz > 0.0 ? t + 1.0 / s->rate_hz : t;
    }
    while (z->len > 0 && z->queue[z->head].t + s->latency_s <= t + 1e-12) {
        z->latest = z->queue[z->head];
        z->head = (z->head + 1) % FIX_QUEUE, z->len--;
    }
    age = t - z->latest.t; /* dead-reckoned from the latest fix */
    north = z->latest.north + z->latest.vn * age;
    east = z->latest.east + z->latest.ve * age;
    if (!z->have_heading || s->compass_lag_s <= 0.0) {
        z->heading = v->heading, z->have_heading = 1;
    } else {
        d = remainder(v->heading - z->heading, 2.0 * PI_D);
        z->heading = wrap_2pi(z->heading + (1.0 - exp(-dt / s->compass_lag_s)) * d);
    }
    lat = v->lat0 + north / EARTH_R * 180.0 / PI_D;
    lon = v->lon0 + east / (EARTH_R * cos(v->lat0 * PI_D / 180.0)) * 180.0 / PI_D;
    sog = sqrt(z->latest.vn * z->latest.vn + z->latest.ve * z->latest.ve);
    memset(nav, 0, sizeof *nav);
    nav->lat_e7 = (int32_t)lround(lat * 1e7);
    nav->lon_e7 = (int32_t)lround(lon * 1e7);
    nav->heading_rad = (float)wrap_2pi(z->heading + rng_normal(z, s->compass_noise_rad));
    nav->course_rad = (float)(sog > 1e-6 ? wrap_2pi(atan2(z->latest.ve, z->latest.vn))
                                         : nav->heading_rad);
    nav->speed_mps = (float)sog;
    nav->yaw_rate = (float)(v->yaw_rate + s->gyro_bias + rng_normal(z, s->gyro_noise));
    nav->battery_mv = 25200;
    nav->battery_pct = 90;
    nav->fix_type = ok ? s->fix_type : 1; /* GPS_FIX_TYPE_NO_FIX in an outage */
    nav->satellites = s->satellites;
}

/* ---- key file: 32 raw bytes or 64 hex digits (whitespace around allowed) */
static int read_key(const char *path, uint8_t key[32])
{
    uint8_t buf[256];
    size_t n, i, k = 0;
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        fprintf(stderr, "usv_boat_host: --link-key %s: %s\n", path, strerror(errno));
        return -1;
    }
    n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    if (n == 32) {
        memcpy(key, buf, 32);
        return 0;
    }
    for (i = 0; i < n; i++) {
        int c = buf[i], d;
        if (c == ' ' || c == '\n' || c == '\r' || c == '\t') {
            continue;
        }
        if (c >= '0' && c <= '9') {
            d = c - '0';
        } else if (c >= 'a' && c <= 'f') {
            d = c - 'a' + 10;
        } else if (c >= 'A' && c <= 'F') {
            d = c - 'A' + 10;
        } else {
            k = 999;
            break;
        }
        if (k >= 64) {
            k = 999;
            break;
        }
        key[k / 2] = (uint8_t)((k % 2) ? (key[k / 2] | d) : (d << 4));
        k++;
    }
    if (k != 64) {
        fprintf(stderr, "usv_boat_host: --link-key %s: not a 32-byte key (32 raw bytes or "
                        "64 hex digits)\n", path);
        return -1;
    }
    return 0;
}

static int open_device(const char *path)
{
    struct termios tio;
    int fd = open(path, O_RDWR | O_NOCTTY | O_NONBLOCK);
    if (fd < 0) {
        fprintf(stderr, "usv_boat_host: cannot open %s: %s\n", path, strerror(errno));
        return -1;
    }
    if (tcgetattr(fd, &tio) == 0) {
        cfmakeraw(&tio);
        tcsetattr(fd, TCSANOW, &tio);
    }
    return fd;
}

static int listen_port(int port, int *bound)
{
    struct sockaddr_in a;
    socklen_t len = sizeof a;
    int one = 1;
    int fd = socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) {
        perror("usv_boat_host: socket");
        return -1;
    }
    setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    memset(&a, 0, sizeof a);
    a.sin_family = AF_INET;
    a.sin_port = htons((uint16_t)port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (bind(fd, (struct sockaddr *)&a, sizeof a) != 0 || listen(fd, 1) != 0) {
        fprintf(stderr, "usv_boat_host: cannot listen on 127.0.0.1:%d: %s\n", port,
                strerror(errno));
        close(fd);
        return -1;
    }
    getsockname(fd, (struct sockaddr *)&a, &len);
    *bound = ntohs(a.sin_port);
    return fd;
}

/* the non-volatile memory: one line "sign_floor N", "sign_floor N exact" after a clean stop */
static uint64_t nv_read(const char *path, int *exact)
{
    unsigned long long v = 0;
    char word[16] = "";
    FILE *f = path != NULL ? fopen(path, "r") : NULL;
    *exact = 0;
    if (f != NULL) {
        int n = fscanf(f, "sign_floor %llu %15s", &v, word);
        if (n < 1) {
            v = 0;
        }
        *exact = n == 2 && strcmp(word, "exact") == 0;
        fclose(f);
    }
    return (uint64_t)v;
}

static void nv_write(const char *path, uint64_t floor, int exact)
{
    char tmp[4096];
    FILE *f;
    if (path == NULL || strlen(path) + 5 >= sizeof tmp) {
        return;
    }
    snprintf(tmp, sizeof tmp, "%s.tmp", path);
    f = fopen(tmp, "w");
    if (f == NULL) {
        return;
    }
    fprintf(f, "sign_floor %llu%s\n", (unsigned long long)floor, exact ? " exact" : "");
    if (fclose(f) == 0) {
        rename(tmp, path); /* atomic: a crash leaves the old floor, never a torn one */
    }
}

static int open_pty(char *name, size_t len, int *slave)
{
    struct termios tio;
    const char *sn;
    int fd = posix_openpt(O_RDWR | O_NOCTTY);
    if (fd < 0 || grantpt(fd) != 0 || unlockpt(fd) != 0 || (sn = ptsname(fd)) == NULL) {
        perror("usv_boat_host: pty");
        return -1;
    }
    snprintf(name, len, "%s", sn);
    *slave = open(name, O_RDWR | O_NOCTTY); /* kept open: the master never sees a hangup */
    if (*slave >= 0 && tcgetattr(*slave, &tio) == 0) {
        cfmakeraw(&tio);
        tcsetattr(*slave, TCSANOW, &tio);
    }
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
    return fd;
}

static int is_port(const char *s)
{
    if (*s == '\0') {
        return 0;
    }
    for (; *s; s++) {
        if (*s < '0' || *s > '9') {
            return 0;
        }
    }
    return 1;
}

static int usage(const char *why)
{
    fprintf(stderr, "usv_boat_host: %s\nusage: usv_boat_host DEVICE|PORT|pty (--link-key PATH | "
                    "--insecure-link) [--boat-id N] [--station-id N] [--speedup X] [--lat DEG] "
                    "[--lon DEG] [--heading-deg DEG] [--telemetry-hz HZ] [--start-radius M] "
                    "[--link-timeout-s S] [--staging-expiry-s S] [--baud BPS] [--duration S] "
                    "[--nv-file PATH] [--sensors exact|rtk|gnss|rtk-moving-base] "
                    "[--seed N]\n", why);
    return 2;
}

static int parse_num(const char *name, const char *s, double lo, double hi, double *out)
{
    char *end;
    double v = strtod(s, &end);
    if (*s == '\0' || *end != '\0' || !(v >= lo && v <= hi)) {
        fprintf(stderr, "usv_boat_host: %s: %s is not a number in [%g, %g]\n", name, s, lo, hi);
        return -1;
    }
    *out = v;
    return 0;
}

static uint32_t random_u32(void)
{
    uint32_t v = 0;
    FILE *f = fopen("/dev/urandom", "rb");
    if (f != NULL) {
        if (fread(&v, sizeof v, 1, f) != 1) {
            v = 0;
        }
        fclose(f);
    }
    if (v == 0) {
        v = (uint32_t)time(NULL) ^ (uint32_t)getpid();
    }
    return v;
}

int main(int argc, char **argv)
{
    static usv_boat_t boat; /* static, as on the microcontroller */
    static host_t host;
    usv_config_t cfg;
    usv_hal_t hal;
    uint8_t key[32];
    const char *where = NULL, *key_path = NULL, *nv_path = NULL, *sensors = "rtk";
    sensor_spec_t spec;
    char pty_name[256];
    char nv_default[4096];
    int pty_slave = -1, floor_exact = 0;
    uint64_t floor_saved = 0;
    double next_nv = 1.0;
    int insecure = 0, listen_fd = -1, port = -1, bound = 0, i;
    double boat_id = 1, station_id = 255, speedup = 1, lat = 59.9, lon = 10.7, heading = 0;
    double tel_hz = 5, radius = 10, timeout_s = 3, duration = 0, staging_s = 30, baud = 0;
    double seed = 0;
    double last_t, sim_t;
    struct timeval tv;

    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *v = i + 1 < argc ? argv[i + 1] : NULL;
        double *num = NULL;
        double lo = 0, hi = 0;
        if (strcmp(a, "--insecure-link") == 0) {
            insecure = 1;
            continue;
        }
        if (a[0] != '-' || a[1] == '\0') {
            if (where != NULL) {
                return usage("more than one DEVICE|PORT");
            }
            where = a;
            continue;
        }
        if (v == NULL) {
            fprintf(stderr, "usv_boat_host: %s needs a value\n", a);
            return 2;
        }
        i++;
        if (strcmp(a, "--link-key") == 0) {
            key_path = v;
            continue;
        } else if (strcmp(a, "--nv-file") == 0) {
            nv_path = v;
            continue;
        } else if (strcmp(a, "--sensors") == 0) {
            sensors = v;
            continue;
        } else if (strcmp(a, "--seed") == 0) {
            num = &seed, lo = 0, hi = 4294967295.0;
        } else if (strcmp(a, "--boat-id") == 0) {
            num = &boat_id, lo = 1, hi = 255;
        } else if (strcmp(a, "--station-id") == 0) {
            num = &station_id, lo = 1, hi = 255;
        } else if (strcmp(a, "--speedup") == 0) {
            num = &speedup, lo = 0.01, hi = 1000;
        } else if (strcmp(a, "--lat") == 0) {
            num = &lat, lo = -89, hi = 89;
        } else if (strcmp(a, "--lon") == 0) {
            num = &lon, lo = -180, hi = 180;
        } else if (strcmp(a, "--heading-deg") == 0) {
            num = &heading, lo = -360, hi = 360;
        } else if (strcmp(a, "--telemetry-hz") == 0) {
            num = &tel_hz, lo = 0.1, hi = 50;
        } else if (strcmp(a, "--start-radius") == 0) {
            num = &radius, lo = 0.1, hi = 100000;
        } else if (strcmp(a, "--link-timeout-s") == 0) {
            num = &timeout_s, lo = 0.1, hi = 3600;
        } else if (strcmp(a, "--baud") == 0) {
            num = &baud, lo = 0, hi = 10000000;
        } else if (strcmp(a, "--staging-expiry-s") == 0) {
            num = &staging_s, lo = 0.1, hi = 3600;
        } else if (strcmp(a, "--duration") == 0) {
            num = &duration, lo = 0, hi = 1e9;
        } else {
            fprintf(stderr, "usv_boat_host: unknown option %s\n", a);
            return 2;
        }
        if (parse_num(a, v, lo, hi, num) != 0) {
            return 2;
        }
    }
    if (where == NULL) {
        return usage("DEVICE|PORT missing");
    }
    if ((key_path == NULL) == !insecure) {
        return usage(key_path == NULL ? "--link-key PATH required (or --insecure-link)"
                                      : "--link-key and --insecure-link exclude each other");
    }
    if ((int)boat_id == (int)station_id) {
        fprintf(stderr, "usv_boat_host: --boat-id and --station-id must differ\n");
        return 2;
    }
    if (key_path != NULL && read_key(key_path, key) != 0) {
        return 2;
    }
    if (sensor_spec(sensors, &spec) != 0) {
        fprintf(stderr, "usv_boat_host: --sensors %s: unknown profile (exact, rtk, gnss, "
                        "rtk-moving-base)\n", sensors);
        return 2;
    }

    memset(&cfg, 0, sizeof cfg);
    cfg.boat_id = (uint8_t)boat_id;
    cfg.station_id = (uint8_t)station_id;
    cfg.key = key_path != NULL ? key : NULL;
    gettimeofday(&tv, NULL); /* signing time: 10 us units since 2015-01-01 00:00:00 UTC */
    cfg.boot_timestamp = ((uint64_t)tv.tv_sec - 1420070400u) * 100000u +
                         (uint64_t)tv.tv_usec / 10u;
    if (nv_path == NULL && key_path != NULL) { /* the default: beside the key */
        if (snprintf(nv_default, sizeof nv_default, "%s.boat%d.floor", key_path,
                     (int)boat_id) < (int)sizeof nv_default) {
            nv_path = nv_default;
        }
    }
    floor_saved = nv_read(nv_path, &floor_exact);
    if (floor_saved != 0u) {
        /* never accept what was seen before the reboot: the floor is written once a second,
           so frames of the last second before it may be newer; 2 s covers them (a clean
           stop wrote the exact last one) */
        uint64_t floor = floor_saved + (floor_exact ? 1u : 200000u);
        if (floor > cfg.boot_timestamp) {
            cfg.boot_timestamp = floor;
        }
        if (floor_exact) {
            nv_write(nv_path, floor_saved, 0); /* a crash from now on keeps the margin */
        }
    }
    cfg.boot_id = random_u32();
    cfg.telemetry_period_ms = (uint32_t)(1000.0 / tel_hz + 0.5);
    /* the link timeouts count link (wall) time, the boat clock runs --speedup faster */
    cfg.link_timeout_ms = (uint32_t)(timeout_s * 1000.0 * speedup + 0.5);
    cfg.dup_expiry_ms = (uint32_t)(USV_DUP_EXPIRY_MS * speedup + 0.5);
    cfg.staging_expiry_ms = (uint32_t)(staging_s * 1000.0 * speedup + 0.5);
    cfg.start_radius_m = (float)radius;
    cfg.max_speed_mps = 4.0f;
    cfg.line_baud = baud > 0 ? (uint32_t)(baud / speedup + 0.5) : 0u; /* in boat time */
    if (baud > 0 && cfg.line_baud == 0u) {
        cfg.line_baud = 1;
    }

    host.fd = -1;
    host.speedup = speedup;
    clock_gettime(CLOCK_MONOTONIC, &host.start);
    host.veh.lat0 = lat;
    host.veh.lon0 = lon;
    host.veh.heading = fmod(heading + 720.0, 360.0) * PI_D / 180.0;
    host.veh.max_speed = cfg.max_speed_mps;
    host.veh.max_yaw_rate = 1.0;
    host.veh.tau = 0.3;
    sensors_init(&host.sens, &spec, (uint64_t)seed);
    hal.send = hal_send;
    hal.now_ms = hal_now_ms;
    hal.actuate = hal_actuate;
    hal.ctx = &host;
    if (usv_boat_init(&boat, &cfg, &hal) != 0) {
        fprintf(stderr, "usv_boat_host: invalid configuration\n");
        return 2;
    }

    signal(SIGINT, on_signal);
    signal(SIGTERM, on_signal);
    signal(SIGPIPE, SIG_IGN);
    if (is_port(where)) {
        port = atoi(where);
        listen_fd = listen_port(port, &bound);
        if (listen_fd < 0) {
            return 1;
        }
        printf("usv_boat_host: boat %d (station %d) listening on 127.0.0.1:%d (%s, speedup %g)\n",
               (int)boat_id, (int)station_id, bound, insecure ? "INSECURE unsigned link"
                                                              : "signed link", speedup);
    } else if (strcmp(where, "pty") == 0) {
        host.fd = open_pty(pty_name, sizeof pty_name, &pty_slave);
        if (host.fd < 0) {
            return 1;
        }
        printf("usv_boat_host: boat %d (station %d) on %s (%s, speedup %g)\n", (int)boat_id,
               (int)station_id, pty_name, insecure ? "INSECURE unsigned link" : "signed link",
               speedup);
    } else {
        host.fd = open_device(where);
        if (host.fd < 0) {
            return 1;
        }
        printf("usv_boat_host: boat %d (station %d) on %s (%s, speedup %g)\n", (int)boat_id,
               (int)station_id, where, insecure ? "INSECURE unsigned link" : "signed link",
               speedup);
    }
    fflush(stdout);

    last_t = wall_s(&host);
    sim_t = 0.0;
    while (!stop_flag) {
        struct pollfd p[2];
        int np = 0, r;
        double now;
        if (host.fd >= 0) {
            p[np].fd = host.fd;
            p[np].events = POLLIN;
            np++;
        }
        if (listen_fd >= 0 && host.fd < 0) {
            p[np].fd = listen_fd;
            p[np].events = POLLIN;
            np++;
        }
        r = poll(p, (nfds_t)np, 5);
        if (r < 0 && errno != EINTR) {
            perror("usv_boat_host: poll");
            break;
        }
        for (i = 0; r > 0 && i < np; i++) {
            if (p[i].fd == listen_fd && (p[i].revents & POLLIN)) {
                int one = 1;
                host.fd = accept(listen_fd, NULL, NULL);
                if (host.fd >= 0) {
                    setsockopt(host.fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
                    fcntl(host.fd, F_SETFL, fcntl(host.fd, F_GETFL) | O_NONBLOCK);
                    printf("usv_boat_host: station connected\n");
                    fflush(stdout);
                }
            } else if (p[i].fd == host.fd && (p[i].revents & (POLLIN | POLLHUP | POLLERR))) {
                uint8_t buf[1024];
                ssize_t n = read(host.fd, buf, sizeof buf);
                ssize_t k;
                for (k = 0; k < n; k++) {
                    usv_boat_rx_byte(&boat, buf[k]); /* the "UART interrupt" */
                    if ((k & 255) == 255) {
                        usv_boat_poll(&boat); /* the main loop keeps up with the ring */
                    }
                }
                if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR)) {
                    if (listen_fd >= 0) {
                        close(host.fd);
                        host.fd = -1;
                        printf("usv_boat_host: station disconnected\n");
                        fflush(stdout);
                    } else if (pty_slave >= 0) {
                        usleep(20000); /* the station closed its side; wait for it */
                    } else if (n == 0 || errno != EIO) {
                        stop_flag = 1; /* the device went away */
                    } else {
                        usleep(20000); /* pty without a master reader yet */
                    }
                }
            }
        }
        now = wall_s(&host);
        /* integrate the vehicle in boat time, in steps of at most 20 ms */
        {
            double target = (now * speedup), dt;
            while (sim_t < target) {
                dt = target - sim_t < 0.02 ? target - sim_t : 0.02;
                vehicle_step(&host.veh, dt);
                sim_t += dt;
            }
        }
        {
            usv_nav_t nav;
            sensors_nav(&host.sens, &host.veh, sim_t, &nav); /* what it measures, not truth */
            usv_boat_set_nav(&boat, &nav);
        }
        usv_boat_poll(&boat);
        last_t = now;
        if (nv_path != NULL && now >= next_nv) {
            uint64_t floor = usv_boat_signing_floor(&boat);
            next_nv = now + 1.0;
            if (floor > floor_saved) {
                nv_write(nv_path, floor, 0);
                floor_saved = floor;
            }
        }
        if (duration > 0 && now >= duration) {
            break;
        }
    }
    (void)last_t;
    if (nv_path != NULL) { /* a clean stop: the exact newest timestamp accepted */
        uint64_t floor = usv_boat_signing_floor(&boat);
        if (floor < floor_saved) {
            floor = floor_saved;
        }
        if (floor != 0u) {
            nv_write(nv_path, floor, 1);
        }
    }
    if (host.fd >= 0) {
        close(host.fd);
    }
    if (pty_slave >= 0) {
        close(pty_slave);
    }
    if (listen_fd >= 0) {
        close(listen_fd);
    }
    printf("usv_boat_host: stopped (state %u, refused %u)\n", (unsigned)boat.state,
           (unsigned)boat.rejected);
    return 0;
}
