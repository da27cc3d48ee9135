/*
 * Plain C reference for tensim's benchmark lattice: the same scene as
 * org.tensim.scene.LatticeScene / LatticeBenchmark (n x n x n nodes, spacing 0.1 m,
 * 1 kg, springs of 1000 N/m between axis neighbours and along both diagonals of
 * every face, in the same order; bottom face y = 0 fixed; gravity -9.81 m/s^2 on y;
 * dt = 1e-3 s), and the same loop: f = m g, then for each spring
 * f_a += k (l - L) / l d, f_b -= the same, d = x_b - x_a.
 *
 * Prints one JSON line per (n, threads): the force pass alone, a symplectic Euler
 * step and a midpoint RK2 step (two force passes), in spring evaluations per second
 * (springs x passes or steps / wall time), best and median of the repeats.
 *
 * Threads (OpenMP): the springs are split in equal contiguous chunks, each thread
 * adds into its own force buffer, and the buffers are summed node by node (the
 * usual way without atomics). With one thread: the plain loop on f itself.
 *
 * Build and run: bench/c/run.sh (gcc -O3 -march=native -fopenmp).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif

typedef struct {
    int n, nodes, springs;
    int *sa, *sb;          /* 3 x node index */
    double *k, *rl;
    double *x, *v, *f, *im, *m;
    double *xm, *vm;
    double *fbuf;          /* threads x 3 nodes */
    int threads;
} Lattice;

static double now(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static void build(Lattice *L, int n, int threads) {
    static const int off[9][3] = {{1,0,0},{0,1,0},{0,0,1},{1,1,0},{1,-1,0},{1,0,1},{1,0,-1},{0,1,1},{0,1,-1}};
    const double h = 0.1;
    L->n = n;
    L->nodes = n * n * n;
    L->threads = threads;
    int cap = 9 * L->nodes;
    L->sa = malloc(sizeof(int) * cap);
    L->sb = malloc(sizeof(int) * cap);
    L->k = malloc(sizeof(double) * cap);
    L->rl = malloc(sizeof(double) * cap);
    size_t n3 = 3 * (size_t) L->nodes;
    L->x = calloc(n3, sizeof(double));
    L->v = calloc(n3, sizeof(double));
    L->f = calloc(n3, sizeof(double));
    L->xm = calloc(n3, sizeof(double));
    L->vm = calloc(n3, sizeof(double));
    L->fbuf = calloc(n3 * threads, sizeof(double));
    L->im = calloc(L->nodes, sizeof(double));
    L->m = calloc(L->nodes, sizeof(double));
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            for (int kk = 0; kk < n; kk++) {
                int id = (i * n + j) * n + kk;
                L->x[3 * id] = i * h;
                L->x[3 * id + 1] = j * h;
                L->x[3 * id + 2] = kk * h;
                L->m[id] = 1;
                L->im[id] = j == 0 ? 0 : 1;
            }
    int s = 0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            for (int kk = 0; kk < n; kk++)
                for (int o = 0; o < 9; o++) {
                    int a = i + off[o][0], b = j + off[o][1], c = kk + off[o][2];
                    if (a < n && b >= 0 && b < n && c >= 0 && c < n) {
                        int p = (i * n + j) * n + kk, q = (a * n + b) * n + c;
                        L->sa[s] = 3 * p;
                        L->sb[s] = 3 * q;
                        double dx = (a - i) * h, dy = (b - j) * h, dz = (c - kk) * h;
                        L->k[s] = 1000;
                        L->rl[s] = sqrt(dx * dx + dy * dy + dz * dz);
                        s++;
                    }
                }
    L->springs = s;
}

static void spring_range(const Lattice *L, const double *restrict x, double *restrict f, int from, int to) {
    const int *restrict sa = L->sa, *restrict sb = L->sb;
    const double *restrict k = L->k, *restrict rl = L->rl;
    for (int i = from; i < to; i++) {
        int a = sa[i], b = sb[i];
        double dx = x[b] - x[a], dy = x[b + 1] - x[a + 1], dz = x[b + 2] - x[a + 2];
        double len = sqrt(dx * dx + dy * dy + dz * dz);
        double sc = len > 0 ? k[i] * (len - rl[i]) / len : 0;
        double fx = sc * dx, fy = sc * dy, fz = sc * dz;
        f[a] += fx; f[a + 1] += fy; f[a + 2] += fz;
        f[b] -= fx; f[b + 1] -= fy; f[b + 2] -= fz;
    }
}

/* f = m g + springs(x). */
static void forces(Lattice *L, const double *x, double *f) {
    const int nn = L->nodes;
    const size_t n3 = 3 * (size_t) nn;
    if (L->threads == 1) {
        for (int i = 0; i < nn; i++) {
            f[3 * i] = 0;
            f[3 * i + 1] = L->m[i] * -9.81;
            f[3 * i + 2] = 0;
        }
        spring_range(L, x, f, 0, L->springs);
        return;
    }
#ifdef _OPENMP
    #pragma omp parallel num_threads(L->threads)
    {
        int t = omp_get_thread_num(), T = omp_get_num_threads();
        double *ft = L->fbuf + n3 * t;
        memset(ft, 0, n3 * sizeof(double));
        int from = (int) ((long) L->springs * t / T), to = (int) ((long) L->springs * (t + 1) / T);
        spring_range(L, x, ft, from, to);
        #pragma omp barrier
        #pragma omp for schedule(static)
        for (int i = 0; i < nn; i++) {
            double fx = 0, fy = L->m[i] * -9.81, fz = 0;
            for (int u = 0; u < T; u++) {
                const double *fu = L->fbuf + n3 * u;
                fx += fu[3 * i]; fy += fu[3 * i + 1]; fz += fu[3 * i + 2];
            }
            f[3 * i] = fx; f[3 * i + 1] = fy; f[3 * i + 2] = fz;
        }
    }
#endif
}

static void step_symplectic(Lattice *L, double dt) {
    forces(L, L->x, L->f);
    const int n3 = 3 * L->nodes;
    #pragma omp parallel for num_threads(L->threads) schedule(static) if (L->threads > 1)
    for (int k = 0; k < n3; k++) {
        double w = L->im[k / 3];
        L->v[k] += dt * w * L->f[k];
        L->x[k] += w != 0 ? dt * L->v[k] : 0;
    }
}

static void step_rk2(Lattice *L, double dt) {
    const int n3 = 3 * L->nodes;
    const double hh = 0.5 * dt;
    forces(L, L->x, L->f);
    #pragma omp parallel for num_threads(L->threads) schedule(static) if (L->threads > 1)
    for (int k = 0; k < n3; k++) {
        double w = L->im[k / 3];
        L->xm[k] = w != 0 ? L->x[k] + hh * L->v[k] : L->x[k];
        L->vm[k] = w != 0 ? L->v[k] + hh * w * L->f[k] : L->v[k];
    }
    forces(L, L->xm, L->f);
    #pragma omp parallel for num_threads(L->threads) schedule(static) if (L->threads > 1)
    for (int k = 0; k < n3; k++) {
        double w = L->im[k / 3];
        if (w != 0) {
            L->x[k] += dt * L->vm[k];
            L->v[k] += dt * w * L->f[k];
        }
    }
}

static void reset(Lattice *L) {
    const double h = 0.1;
    int n = L->n;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            for (int kk = 0; kk < n; kk++) {
                int id = (i * n + j) * n + kk;
                L->x[3 * id] = i * h; L->x[3 * id + 1] = j * h; L->x[3 * id + 2] = kk * h;
            }
    memset(L->v, 0, 3 * sizeof(double) * L->nodes);
}

static int cmp(const void *a, const void *b) {
    double x = *(const double *) a, y = *(const double *) b;
    return x < y ? -1 : x > y;
}

static double median(double *a, int r) {
    qsort(a, r, sizeof(double), cmp);
    return r % 2 ? a[r / 2] : 0.5 * (a[r / 2 - 1] + a[r / 2]);
}

static double best(double *a, int r) {
    double b = a[0];
    for (int i = 1; i < r; i++) b = a[i] > b ? a[i] : b;
    return b;
}

int main(int argc, char **argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: %s N[,N...] T[,T...] [repeats]\n", argv[0]);
        return 2;
    }
    int repeats = argc > 3 ? atoi(argv[3]) : 5;
    if (repeats < 1 || repeats > 100) repeats = 5;
    char nbuf[256], tbuf[256];
    snprintf(nbuf, sizeof nbuf, "%s", argv[1]);
    for (char *ns = strtok(nbuf, ","); ns; ns = strtok(NULL, ",")) {
        int n = atoi(ns);
        snprintf(tbuf, sizeof tbuf, "%s", argv[2]);
        char *save;
        for (char *ts = strtok_r(tbuf, ",", &save); ts; ts = strtok_r(NULL, ",", &save)) {
            int threads = atoi(ts);
#ifndef _OPENMP
            if (threads != 1) { fprintf(stderr, "built without OpenMP: threads must be 1\n"); return 2; }
#endif
            Lattice L;
            build(&L, n, threads);
            int passes = (int) fmax(5, 2e7 / L.springs);
            double fp[100], se[100], rk[100];
            for (int i = 0; i < passes; i++) forces(&L, L.x, L.f); /* warm-up */
            for (int r = 0; r < repeats; r++) {
                double t0 = now();
                for (int i = 0; i < passes; i++) forces(&L, L.x, L.f);
                fp[r] = (double) L.springs * passes / (now() - t0);
            }
            int steps = (int) fmax(10, fmin(5000, 2e7 / L.springs));
            for (int r = 0; r < repeats; r++) {
                reset(&L);
                double t0 = now();
                for (int i = 0; i < steps; i++) step_symplectic(&L, 1e-3);
                se[r] = (double) L.springs * steps / (now() - t0);
            }
            int rsteps = steps / 2 > 10 ? steps / 2 : 10;
            for (int r = 0; r < repeats; r++) {
                reset(&L);
                double t0 = now();
                for (int i = 0; i < rsteps; i++) step_rk2(&L, 1e-3);
                rk[r] = (double) L.springs * rsteps / (now() - t0);
            }
            double check = L.x[3 * L.nodes - 2];
            printf("{\"impl\":\"c\",\"scene\":\"lattice\",\"n\":%d,\"nodes\":%d,\"springs\":%d,\"threads\":%d,"
                   "\"repeats\":%d,\"force_pass_springs_per_s\":%.4g,\"force_pass_springs_per_s_median\":%.4g,"
                   "\"symplectic_step_springs_per_s\":%.4g,\"symplectic_step_springs_per_s_median\":%.4g,"
                   "\"rk2_step_springs_per_s\":%.4g,\"rk2_step_springs_per_s_median\":%.4g,\"check\":%.6g}\n",
                   n, L.nodes, L.springs, threads, repeats, best(fp, repeats), median(fp, repeats),
                   best(se, repeats), median(se, repeats), best(rk, repeats), median(rk, repeats), check);
            fflush(stdout);
        }
    }
    return 0;
}
