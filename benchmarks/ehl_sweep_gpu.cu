// The x-line relaxation sweep of asperity.ehl.kernels (line_sweep, _relax_row, the block-band
// elimination and the active set), its flow factors (asperity.ehl.lubricant._flow_field:
// Roelands or Barus, Dowson-Higginson, Eyring) and the far-field pass (far_field) in CUDA C,
// for benchmarks/ehl_sweep_gpu.py. The same operations in the same order as the compiled CPU
// kernels; one thread per row of one colour of the zebra sweep.
//
// Fields are (nx, ny) in C order (y fastest), so that the threads of a warp, which hold
// neighbouring rows j, read neighbouring addresses; the row solve's stored rows are laid out
// the same way (element s of block row i of thread j at (i NS + s) ny + j).
//
// The row solve: a colour has ~100 rows, so ~100 threads, each eliminating its row's nodes in
// sequence; it is bound by memory latency. A direct port that kept the row's block band in
// global scratch and eliminated it right-looking, as _block_band_solve does, took 17 ms for
// the two colours of 801 x 201 on an H100 (docs/ehl-transient.md, "The sweep on a GPU").
// relax_rows assembles each block row in registers when it is eliminated (left-looking: row
// i takes the updates of pivot rows i - BL .. i - 1 in increasing order, the order in which
// the right-looking loop applies them, so every entry sees the same operations in the same
// order), keeps the last BL eliminated rows in registers, stores only what the back
// substitution needs (inverse pivot, column 0 of the blocks right of it, its u11, the
// eliminated right-hand side) and loads each row's inputs one row ahead: 3.1 ms.

#define FLUID 0
#define CAVITATED 1
#define CONTACT 2

#define F(a, i, j) a[(size_t)(i) * ny + (j)]
#define X(i, r) x[((size_t)(i) * 2 + (r)) * ny + j]

struct Params {
    int nx, ny, kn;
    double lam, dx, dy, theta, mass, c_el;
};

// the parameters travel as two small arrays: qi = (nx, ny, kn), qd = (lam, dx, dy, theta,
// mass, c_el); the band widths BL, BU of the row solve are compiled in (-DBL=, -DBU=)
__device__ inline Params params(const int *qi, const double *qd) {
    Params q;
    q.nx = qi[0]; q.ny = qi[1]; q.kn = qi[2];
    q.lam = qd[0]; q.dx = qd[1]; q.dy = qd[2]; q.theta = qd[3]; q.mass = qd[4]; q.c_el = qd[5];
    return q;
}

__device__ inline void upwind(int i, double *c0, double *c1, double *c2) {
    if (i >= 2) { *c0 = 1.5; *c1 = 2.0; *c2 = 0.5; }
    else { *c0 = 1.0; *c1 = 1.0; *c2 = 0.0; }
}

// (A0, B0, R^, E^) of the point update at node (i, j): _nodal_coefficients
__device__ void nodal(const double *p, const double *h, const double *ex, const double *ey,
                      const double *rho, const double *efar, const double *rhs_t,
                      const double *f_near, const Params &q, int i, int j,
                      double *a0, double *b0, double *r, double *e) {
    const int nx = q.nx, ny = q.ny;
    const double dx2 = q.dx * q.dx, dy2 = q.dy * q.dy, inv_dy2 = 1.0 / dy2;
    double ep = F(ex, i, j), eq = F(ey, i, j);
    double xe = 0.5 * (ep + F(ex, i + 1, j)) / dx2, xw = 0.5 * (ep + F(ex, i - 1, j)) / dx2;
    double xn = 0.5 * (eq + F(ey, i, j + 1)) / dy2, xs = 0.5 * (eq + F(ey, i, j - 1)) / dy2;
    double c0, c1, c2;
    upwind(i, &c0, &c1, &c2);
    double nb = xe * F(p, i + 1, j) + xw * F(p, i - 1, j);
    nb += xn * F(p, i, j + 1) + xs * F(p, i, j - 1);
    double hy = (F(h, i, j + 1) + F(h, i, j - 1)) * inv_dy2;
    double rho_ww_h = i >= 2 ? F(rho, i - 2, j) * F(h, i - 2, j) : 0.0;
    *a0 = -q.theta * (xe + xw + xn + xs);
    *b0 = -q.theta * q.lam * F(rho, i, j) * c0 / q.dx - q.mass * F(rho, i, j);
    double rr = -q.theta * (nb + q.lam * (c1 * F(rho, i - 1, j) * F(h, i - 1, j)
                                          - c2 * rho_ww_h) / q.dx);
    *r = rr - F(rhs_t, i, j);
    double ee = F(efar, i, j) - (F(h, i + 1, j) + F(h, i - 1, j)) / dx2 - hy;
    for (int k = -q.kn; k <= q.kn; k++)
        if (k != 0 && 0 < i + k && i + k < nx - 1) ee += q.c_el * f_near[abs(k)] * F(p, i + k, j);
    *e = ee;
}


#ifndef BL
#define BL 2
#endif
#ifndef BU
#define BU 2
#endif
#define NW (BL + BU + 1)
#define NS (4 + 2 * BU + 3)
#define S(i, s) sdata[((size_t)(i) * NS + (s)) * ny + j]

// the inputs of block row i of row j, loaded together (issued one row ahead of their use,
// so that their memory latency overlaps the elimination of the row before)
struct RowInputs {
    signed char kind;
    double h, h_n, h_s, efar, ex, ex_e, ex_w, ey, ey_n, ey_s, p, p_e, p_w, p_n, p_s, dex, dey,
        rho, rho_w, rho_ww, rhs_t;
};

__device__ inline RowInputs load_row(
        const double *__restrict__ p, const double *__restrict__ h,
        const double *__restrict__ ex, const double *__restrict__ ey,
        const double *__restrict__ rho, const double *__restrict__ efar,
        const double *__restrict__ rhs_t, const double *__restrict__ dex,
        const double *__restrict__ dey, const signed char *__restrict__ kind, int nx, int ny,
        int i, int j) {
    RowInputs r;
    r.h = F(h, i, j);
    r.kind = F(kind, i, j);
    if (i == 0 || i == nx - 1) return r;
    r.h_n = F(h, i, j + 1); r.h_s = F(h, i, j - 1); r.efar = F(efar, i, j);
    r.ex = F(ex, i, j); r.ex_e = F(ex, i + 1, j); r.ex_w = F(ex, i - 1, j);
    r.ey = F(ey, i, j); r.ey_n = F(ey, i, j + 1); r.ey_s = F(ey, i, j - 1);
    r.p = F(p, i, j); r.p_e = F(p, i + 1, j); r.p_w = F(p, i - 1, j);
    r.p_n = F(p, i, j + 1); r.p_s = F(p, i, j - 1);
    r.dex = F(dex, i, j); r.dey = F(dey, i, j);
    r.rho = F(rho, i, j); r.rho_w = F(rho, i - 1, j); r.rho_ww = i >= 2 ? F(rho, i - 2, j) : 0.0;
    r.rhs_t = F(rhs_t, i, j);
    return r;
}

// block row i (_assemble_row) from its inputs into A (offsets -BL..BU) and bb
__device__ inline void assemble_block_row(const RowInputs &r, const double *__restrict__ f_near,
                                          const Params &q, int i, double A[NW][2][2],
                                          double bb[2]) {
    const int nx = q.nx;
    const double dx2 = q.dx * q.dx, dy2 = q.dy * q.dy, inv_dy2 = 1.0 / dy2;
    const double d0 = -2.0 / dx2 - 2.0 * inv_dy2;
#pragma unroll
    for (int c = 0; c < NW; c++) {
        A[c][0][0] = 0.0; A[c][0][1] = 0.0; A[c][1][0] = 0.0; A[c][1][1] = 0.0;
    }
    if (i == 0 || i == nx - 1) {
        A[BL][0][0] = 1.0; bb[0] = 0.0; A[BL][1][1] = 1.0; bb[1] = r.h;
        return;
    }
    double hy = (r.h_n + r.h_s) * inv_dy2;
    A[BL][1][1] = d0;
    A[BL + 1][1][1] = 1.0 / dx2;
    A[BL - 1][1][1] = 1.0 / dx2;
#pragma unroll
    for (int k = -BL; k <= BU; k++) {
        int ak = k < 0 ? -k : k;
        if (ak <= q.kn && 0 < i + k && i + k < nx - 1) A[BL + k][1][0] -= q.c_el * f_near[ak];
    }
    bb[1] = r.efar - hy;
    if (r.kind == CAVITATED) { A[BL][0][0] = 1.0; bb[0] = 0.0; return; }
    if (r.kind == CONTACT) { A[BL][0][1] = 1.0; bb[0] = 0.0; return; }
    double xe = 0.5 * (r.ex + r.ex_e) / dx2, xw = 0.5 * (r.ex + r.ex_w) / dx2;
    double xn = 0.5 * (r.ey + r.ey_n) / dy2, xs = 0.5 * (r.ey + r.ey_s) / dy2;
    double c0, c1, c2;
    upwind(i, &c0, &c1, &c2);
    double g = r.dex * (r.p_e + r.p_w - 2.0 * r.p) / dx2;
    g += r.dey * (r.p_n + r.p_s - 2.0 * r.p) / dy2;
    g *= 0.5 * q.theta;
    double newton = g < 0.0 ? g : 0.0;
    A[BL][0][0] = -q.theta * (xe + xw + xn + xs) + newton;
    A[BL + 1][0][0] = q.theta * xe;
    A[BL - 1][0][0] = q.theta * xw;
    A[BL][0][1] = -q.theta * q.lam * r.rho * c0 / q.dx - q.mass * r.rho;
    A[BL - 1][0][1] = q.theta * q.lam * c1 * r.rho_w / q.dx;
    if (i >= 2) A[BL - 2][0][1] = -q.theta * q.lam * c2 * r.rho_ww / q.dx;
    double nb = xn * r.p_n + xs * r.p_s;
    bb[0] = -q.theta * nb - r.rhs_t + newton * r.p;
}

// the release of cavitated / contact nodes by the point update at the current iterate (the
// start of _relax_row), at every node of the rows of one colour at once (a node's release
// reads only its own kind); launched before relax_rows
extern "C" __global__ void release_nodes(
        const double *__restrict__ p, const double *__restrict__ h,
        const double *__restrict__ ex, const double *__restrict__ ey,
        const double *__restrict__ rho, const double *__restrict__ efar,
        const double *__restrict__ rhs_t, signed char *__restrict__ kind,
        const double *__restrict__ f_near, const int *qi, const double *qd, int first,
        int count) {
    int t = blockIdx.x * blockDim.x + threadIdx.x;
    const Params q = params(qi, qd);
    const int nx = q.nx, ny = q.ny;
    if (t >= count * (nx - 2)) return;
    const int j = first + 2 * (t % count), i = 1 + t / count;
    signed char kd = F(kind, i, j);
    if (kd == FLUID) return;
    const double dx2 = q.dx * q.dx, inv_dy2 = 1.0 / (q.dy * q.dy);
    const double d0 = -2.0 / dx2 - 2.0 * inv_dy2;
    const double c_self = -q.c_el * f_near[0];
    double a0, b0, r, e;
    nodal(p, h, ex, ey, rho, efar, rhs_t, f_near, q, i, j, &a0, &b0, &r, &e);
    double det = a0 * d0 - b0 * c_self;
    if (kd == CAVITATED && (r * d0 - b0 * e) / det > 0.0) F(kind, i, j) = FLUID;
    else if (kd == CONTACT && (a0 * e - c_self * r) / det > 0.0) F(kind, i, j) = FLUID;
}

// the rows of one colour after release_nodes: assembly, elimination, back substitution and
// active set of _relax_row
extern "C" __global__ void relax_rows(
        double *__restrict__ p, double *__restrict__ h, const double *__restrict__ ex,
        const double *__restrict__ ey, const double *__restrict__ rho,
        const double *__restrict__ efar, const double *__restrict__ rhs_t,
        const double *__restrict__ dex, const double *__restrict__ dey,
        signed char *__restrict__ kind, const double *__restrict__ f_near, const int *qi,
        const double *qd, int first, int count, double *__restrict__ sdata,
        double *__restrict__ x, double *__restrict__ dp_row, double *__restrict__ dh_row) {
    int t = blockIdx.x * blockDim.x + threadIdx.x;
    if (t >= count) return;
    const Params q = params(qi, qd);
    const int j = first + 2 * t;
    const int nx = q.nx, ny = q.ny;
    int start = 0;
    for (int pass = 0; pass < 4; pass++) {
        // window: the eliminated rows i - BL .. i - 1 (slot s holds row i - BL + s)
        double winv[BL][4], wu[BL][BU][2], wu11[BL], wb[BL][2];
#pragma unroll
        for (int s = 0; s < BL; s++) {
            int k = start - BL + s;
            if (k < 0) continue;
#pragma unroll
            for (int e = 0; e < 4; e++) winv[s][e] = S(k, e);
#pragma unroll
            for (int u = 0; u < BU; u++) { wu[s][u][0] = S(k, 4 + 2 * u); wu[s][u][1] = S(k, 5 + 2 * u); }
            wu11[s] = S(k, 4 + 2 * BU);
            wb[s][0] = S(k, 5 + 2 * BU); wb[s][1] = S(k, 6 + 2 * BU);
        }
        RowInputs next = load_row(p, h, ex, ey, rho, efar, rhs_t, dex, dey, kind, nx, ny,
                                  start, j);
        for (int i = start; i < nx; i++) {
            const RowInputs cur = next;
            if (i + 1 < nx)
                next = load_row(p, h, ex, ey, rho, efar, rhs_t, dex, dey, kind, nx, ny, i + 1, j);
            double A[NW][2][2], bb[2];
            assemble_block_row(cur, f_near, q, i, A, bb);
#pragma unroll
            for (int s = 0; s < BL; s++) {
                int k = i - BL + s;
                if (k < 0) continue;
                double a00 = A[s][0][0], a01 = A[s][0][1], a10 = A[s][1][0], a11 = A[s][1][1];
                if (a00 == 0.0 && a01 == 0.0 && a10 == 0.0 && a11 == 0.0) continue;
                double l00 = a00 * winv[s][0] + a01 * winv[s][2];
                double l01 = a00 * winv[s][1] + a01 * winv[s][3];
                double l10 = a10 * winv[s][0] + a11 * winv[s][2];
                double l11 = a10 * winv[s][1] + a11 * winv[s][3];
                A[s + 1][0][1] -= l01 * wu11[s];
                A[s + 1][1][1] -= l11 * wu11[s];
#pragma unroll
                for (int u = 1; u <= BU; u++) {
                    if (k + u > nx - 1) break;
                    double u00 = wu[s][u - 1][0], u10 = wu[s][u - 1][1];
                    A[s + u][0][0] -= l00 * u00 + l01 * u10;
                    A[s + u][1][0] -= l10 * u00 + l11 * u10;
                }
                bb[0] -= l00 * wb[s][0] + l01 * wb[s][1];
                bb[1] -= l10 * wb[s][0] + l11 * wb[s][1];
            }
            double d00 = A[BL][0][0], d01 = A[BL][0][1], d10 = A[BL][1][0], d11 = A[BL][1][1];
            double inv = 1.0 / (d00 * d11 - d01 * d10);
            double ninv[4] = {d11 * inv, -d01 * inv, -d10 * inv, d00 * inv};
            // store for the back substitution and shift the window
#pragma unroll
            for (int e = 0; e < 4; e++) S(i, e) = ninv[e];
#pragma unroll
            for (int u = 0; u < BU; u++) {
                S(i, 4 + 2 * u) = A[BL + 1 + u][0][0];
                S(i, 5 + 2 * u) = A[BL + 1 + u][1][0];
            }
            S(i, 4 + 2 * BU) = A[BL + 1][1][1];
            S(i, 5 + 2 * BU) = bb[0];
            S(i, 6 + 2 * BU) = bb[1];
#pragma unroll
            for (int s = 0; s < BL - 1; s++) {
#pragma unroll
                for (int e = 0; e < 4; e++) winv[s][e] = winv[s + 1][e];
#pragma unroll
                for (int u = 0; u < BU; u++) { wu[s][u][0] = wu[s + 1][u][0]; wu[s][u][1] = wu[s + 1][u][1]; }
                wu11[s] = wu11[s + 1]; wb[s][0] = wb[s + 1][0]; wb[s][1] = wb[s + 1][1];
            }
#pragma unroll
            for (int e = 0; e < 4; e++) winv[BL - 1][e] = ninv[e];
#pragma unroll
            for (int u = 0; u < BU; u++) {
                wu[BL - 1][u][0] = A[BL + 1 + u][0][0]; wu[BL - 1][u][1] = A[BL + 1 + u][1][0];
            }
            wu11[BL - 1] = A[BL + 1][1][1];
            wb[BL - 1][0] = bb[0]; wb[BL - 1][1] = bb[1];
        }
        // back substitution with the active set inline (_update_active_set: the first node
        // moved is the smallest i moved)
        double xw[BU][2];  // x of rows k + 1 .. k + BU
#pragma unroll
        for (int u = 0; u < BU; u++) { xw[u][0] = 0.0; xw[u][1] = 0.0; }
        int moved = nx;
        double nxt[NS];  // the stored row k - 1, loaded one row ahead
#pragma unroll
        for (int e = 0; e < NS; e++) nxt[e] = S(nx - 1, e);
        for (int k = nx - 1; k >= 0; k--) {
            double sk[NS];
#pragma unroll
            for (int e = 0; e < NS; e++) sk[e] = nxt[e];
            if (k > 0) {
#pragma unroll
                for (int e = 0; e < NS; e++) nxt[e] = S(k - 1, e);
            }
            double s0 = sk[5 + 2 * BU], s1 = sk[6 + 2 * BU];
#pragma unroll
            for (int u = 1; u <= BU; u++) {
                if (k + u > nx - 1) break;
                s0 -= sk[2 + 2 * u] * xw[u - 1][0];
                if (u == 1) s1 -= sk[3 + 2 * u] * xw[0][0] + sk[4 + 2 * BU] * xw[0][1];
                else s1 -= sk[3 + 2 * u] * xw[u - 1][0];
            }
            double x0 = sk[0] * s0 + sk[1] * s1;
            double x1 = sk[2] * s0 + sk[3] * s1;
            X(k, 0) = x0;
            X(k, 1) = x1;
#pragma unroll
            for (int u = BU - 1; u > 0; u--) { xw[u][0] = xw[u - 1][0]; xw[u][1] = xw[u - 1][1]; }
            xw[0][0] = x0; xw[0][1] = x1;
            if (k >= 1 && k < nx - 1) {
                signed char old = F(kind, k, j), kd = old;
                if (old == FLUID && x0 < 0.0) kd = CAVITATED;
                else if (old != CONTACT && x1 < 0.0) kd = CONTACT;
                else if (old == CONTACT && x0 < 0.0) kd = CAVITATED;
                if (kd != old) { F(kind, k, j) = kd; moved = k; }
            }
        }
        start = moved;
        if (start == nx) break;
    }
    double dp_max = 0.0, dh_max = 0.0;
    for (int i = 1; i < nx - 1; i++) {
        double pn = fmax(X(i, 0), 0.0), hn = fmax(X(i, 1), 0.0);
        dp_max = fmax(dp_max, fabs(pn - F(p, i, j)));
        dh_max = fmax(dh_max, fabs(hn - F(h, i, j)));
        F(p, i, j) = pn;
        F(h, i, j) = hn;
    }
    dp_row[j] = dp_max;
    dh_row[j] = dh_max;
}

// ---- flow factors (_flow_field, _pressure_laws, _eyring_x, _eyring_y) ----

// lubricant parameters, as an array ld = (p_unit, h_unit, s_unit, ds_unit, roelands, eta0,
// v1, v2, v3, gamma, lam, shear) (Lubricant.flow_field)
struct Lub {
    double p_unit, h_unit, s_unit, ds_unit;
    int roelands;
    double eta0, v1, v2, v3, gamma, lam, shear;
};

__device__ void pressure_laws(double p, const Lub &L, double *eta, double *deta, double *r,
                              double *dr) {
    double pp = fmax(p, 0.0);
    if (L.roelands) {
        double qq = 1.0 + L.v2 * pp, t = pow(qq, L.v3);
        *eta = L.eta0 * exp(L.v1 * (t - 1.0));
        *deta = *eta * L.v1 * L.v3 * L.v2 * t / qq;
    } else {
        *eta = L.eta0 * exp(L.v1 * pp);
        *deta = L.v1 * *eta;
    }
    if (isinf(*eta)) *deta = 0.0;
    double qd = 1.0 + L.lam * pp;
    *r = (1.0 + L.gamma * pp) / qd;
    *dr = (L.gamma - L.lam) / (qd * qd);
}

__device__ void eyring_x(double h, double eta, double shear, double *f, double *df) {
    if (h <= 0.0) { *f = 0.0; *df = 0.0; return; }
    double u = h / eta, root = sqrt(u * u + shear * shear);
    if (root == 0.0) { *f = 0.0; *df = 0.0; return; }
    *f = h * h * root / 12.0;
    *df = -h * h * u * u / (12.0 * eta * root);
}

__device__ void eyring_y(double h, double eta, double shear, double *f, double *df) {
    if (h <= 0.0) { *f = 0.0; *df = 0.0; return; }
    double x = shear > 0.0 ? eta * shear / h : 0.0;
    if (isinf(x)) { *f = 0.0; *df = 0.0; return; }
    double g, dg;
    if (x < 1e-4) {
        g = (1.0 + x * x / 6.0) / eta;
        dg = -1.0 / (eta * eta);
        if (shear > 0.0) dg += shear * shear / (6.0 * h * h);
    } else {
        double s = asinh(x);
        g = x / (eta * s);
        double sh = shear / h;
        dg = -sh * sh / (s * s * sqrt(1.0 + x * x));
    }
    *f = h * h * h * g / 12.0;
    *df = h * h * h * dg / 12.0;
}

extern "C" __global__ void flow_field(const double *p, const double *h, const double *ld,
                                      int n, int slopes, double *sx, double *sy, double *rho,
                                      double *dsx, double *dsy) {
    int k = blockIdx.x * blockDim.x + threadIdx.x;
    if (k >= n) return;
    Lub L;
    L.p_unit = ld[0]; L.h_unit = ld[1]; L.s_unit = ld[2]; L.ds_unit = ld[3];
    L.roelands = ld[4] != 0.0; L.eta0 = ld[5]; L.v1 = ld[6]; L.v2 = ld[7]; L.v3 = ld[8];
    L.gamma = ld[9]; L.lam = ld[10]; L.shear = ld[11];
    double pk = p[k] * L.p_unit, hk = fmax(h[k] * L.h_unit, 0.0);
    double eta, deta, r, dr, fx, dfx, fy, dfy;
    pressure_laws(pk > 0.0 ? pk : 0.0, L, &eta, &deta, &r, &dr);
    eyring_x(hk, eta, L.shear, &fx, &dfx);
    eyring_y(hk, eta, L.shear, &fy, &dfy);
    sx[k] = r * fx * L.s_unit;
    sy[k] = r * fy * L.s_unit;
    rho[k] = r;
    if (slopes) {
        dsx[k] = (fx * dr + r * dfx * deta) * L.ds_unit;
        dsy[k] = (fy * dr + r * dfy * deta) * L.ds_unit;
    }
}

// ---- far field (far_field, _laplacian_column) and oscillation damping ----

extern "C" __global__ void far_field(const double *w, const double *p, const double *source,
                                     const double *f_near, const int *qi, const double *qd,
                                     double *efar) {
    int k = blockIdx.x * blockDim.x + threadIdx.x;
    const Params q = params(qi, qd);
    const int nx = q.nx, ny = q.ny;
    if (k >= nx * ny) return;
    int i = k / ny, j = k % ny;
    const double dx2 = q.dx * q.dx, dy2 = q.dy * q.dy;
    double lap = 0.0;
    if (i > 0 && i < nx - 1 && j > 0 && j < ny - 1)
        lap = (F(w, i + 1, j) - 2.0 * F(w, i, j) + F(w, i - 1, j)) / dx2
              + (F(w, i, j + 1) - 2.0 * F(w, i, j) + F(w, i, j - 1)) / dy2;
    double near = f_near[0] * F(p, i, j);
    for (int kk = 1; kk <= q.kn; kk++) {
        if (i >= kk) near += f_near[kk] * F(p, i - kk, j);
        if (i + kk < nx) near += f_near[kk] * F(p, i + kk, j);
    }
    F(efar, i, j) = F(source, i, j) + q.c_el * (lap - near);
}

extern "C" __global__ void damp(double *p, double *h, const double *p_before,
                                const double *h_before, double *last_change, double damping,
                                int has_last, int n) {
    int k = blockIdx.x * blockDim.x + threadIdx.x;
    if (k >= n) return;
    double change = p[k] - p_before[k];
    if (has_last && change * last_change[k] < 0.0) {
        change *= damping;
        p[k] = p_before[k] + change;
        h[k] = h_before[k] + damping * (h[k] - h_before[k]);
    }
    last_change[k] = change;
}
