/* polycontact.c: exact overlap of convex polyhedra and YADE's volumetric
 * contact law, for the triaxial scenes (loaded with ctypes by shapes/ckernel.py).
 *
 * Geometry. A convex polyhedron is a set of outward triangles. The overlap
 * A n B is built by clipping A's triangles by every face plane of B
 * (Sutherland-Hodgman in 3D): each plane cuts the current convex polygons and
 * closes the hole with a cap polygon on that plane. In exact arithmetic the
 * result is the overlap polyhedron; in doubles it is exact to round-off (no
 * face merging, no tolerance). All coordinates are relative to A's centre, so
 * round-off scales with the grain size, not with the position in the box.
 *
 *   V        volume of the overlap (divergence theorem, tetrahedra from a
 *            vertex of the overlap)
 *   c        its centroid: the contact point
 *   S_A      sum over the overlap's faces lying on A's surface of
 *            (area x A's outward normal) = -dV/dx_B
 *   n        S_A / |S_A|, from A to B
 *   shadow   the overlap projected on the plane normal to n (a convex
 *            polygon: the 2D hull of the projected vertices); its area, and its
 *            widths (max - min of the projected vertices) along the principal
 *            axes of its second moment of area, largest first.
 *
 * Contact law (YADE's Law2_PolyhedraGeom_PolyhedraPhys_Volumetric normal
 * part, per-contact tangential part):
 *   F_n = k_V V n on B (A receives -F_n), applied at c;
 *   f_t <- f_t projected on the new tangent plane (norm kept), turned by the
 *          pair's mean spin about n, then f_t -= k_t du_t with du_t the
 *          tangential displacement of B's material point at c relative to
 *          A's over the step, and |f_t| <= mu |F_n|.
 *
 * No allocation on the per-step path except when the neighbour list grows.
 * OpenMP over pairs; each thread has its own clipping workspace.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#define PC_OK 0
#define PC_DEGENERATE_NORMAL 1   /* |S_A| ~ 0: normal from the centres (or z) */
#define PC_WORKSPACE 2           /* workspace overflow (should not happen)    */
#define PC_MASK_WORDS 4          /* words of a face's vertex set (shapes of up to 256 vertices) */
#define PC_HASH 256              /* slots of a cut's crossing-edge table (a power of two) */
#define PC_PARALLEL_MIN 400      /* pairs + body-wall tests below which a step runs on one thread
                                  * (POLYCONTACT_PARALLEL_MIN overrides it when an engine is made:
                                  * the tests run tiny scenes on the parallel path) */

/* ------------------------------------------------------------------ small vector helpers */
static inline double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static inline void cross3(const double *a, const double *b, double *c) {
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}
static void quat_to_mat(const double *q, double *R) {
    /* q = (w, x, y, z), normalised here; R row-major, local -> global */
    double w = q[0], x = q[1], y = q[2], z = q[3];
    double s = sqrt(w * w + x * x + y * y + z * z);
    if (s > 0) { w /= s; x /= s; y /= s; z /= s; } else { w = 1; x = y = z = 0; }
    R[0] = 1 - 2 * (y * y + z * z); R[1] = 2 * (x * y - w * z);     R[2] = 2 * (x * z + w * y);
    R[3] = 2 * (x * y + w * z);     R[4] = 1 - 2 * (x * x + z * z); R[5] = 2 * (y * z - w * x);
    R[6] = 2 * (x * z - w * y);     R[7] = 2 * (y * z + w * x);     R[8] = 1 - 2 * (x * x + y * y);
}
static inline void matvec(const double *R, const double *v, double *o) {
    o[0] = R[0] * v[0] + R[1] * v[1] + R[2] * v[2];
    o[1] = R[3] * v[0] + R[4] * v[1] + R[5] * v[2];
    o[2] = R[6] * v[0] + R[7] * v[1] + R[8] * v[2];
}
static inline void mattvec(const double *R, const double *v, double *o) {
    o[0] = R[0] * v[0] + R[3] * v[1] + R[6] * v[2];
    o[1] = R[1] * v[0] + R[4] * v[1] + R[7] * v[2];
    o[2] = R[2] * v[0] + R[5] * v[1] + R[8] * v[2];
}

/* ------------------------------------------------------------------ posed polyhedron */
/* A polyhedron placed in a frame: nv vertices (x, y, z), nt outward triangles,
 * one plane per triangle (unit normal n, offset h: inside is n.x <= h). */
typedef struct {
    int nv, nt;
    const double *v;    /* nv x 3 */
    const int *t;       /* nt x 3 */
    const double *n;    /* nt x 3 */
    const double *h;    /* nt     */
    const double *R;    /* 3 x 3 rotation (local -> frame), or NULL */
    const double *box;  /* local bounding box lo[3], hi[3], or NULL */
    const unsigned char *dup;  /* per triangle: 1 if its plane repeats an earlier triangle's, or NULL */
    double off[3];      /* position of the local origin in the frame */
    const uint64_t *pmask;     /* per triangle: PC_MASK_WORDS words, the vertices of its plane's whole face
                                * (every triangle of that plane); NULL for a shape without coplanar triangles */
    /* the shape's polygonal faces (its coplanar triangles merged, see table_init), or nf = 0: its
     * triangles are its faces. Face k: fc[k] vertices fi[fs[k] ...] counter-clockwise seen from
     * outside, its plane that of triangle ftag[k] (the first of that plane) */
    int nf;
    const int *fs, *fc, *fi, *ftag;
    double ra;          /* largest |x| + |y| + |z| of the vertices v, or 0: not known (see posed_extent) */
    /* or NULL: the planes by face, normals pn (nf x 3) and offsets ph (nf), tplane[t] the face of
     * triangle t's plane (t a face's first triangle); overlap_kept reads the planes through
     * plane_n and plane_h, which fall back on n and h by triangle */
    const double *pn, *ph;
    const int *tplane;
} posed_t;

static inline const double *plane_n(const posed_t *P, int t) { return P->pn ? P->pn + 3 * P->tplane[t] : P->n + 3 * t; }
static inline double plane_h(const posed_t *P, int t) { return P->pn ? P->ph[P->tplane[t]] : P->h[t]; }

/* The largest |x| + |y| + |z| of A's vertices (the scale of its round-off). */
static inline double posed_extent(const posed_t *A) {
    if (A->ra > 0) return A->ra;
    double ra = 0;
    for (int i = 0; i < A->nv; i++) {
        double q = fabs(A->v[3 * i]) + fabs(A->v[3 * i + 1]) + fabs(A->v[3 * i + 2]);
        ra = q > ra ? q : ra;
    }
    return ra;
}

/* ------------------------------------------------------------------ clipping workspace */
typedef struct {
    int cap_poly, cap_pts;
    /* two polygon buffers (double buffering) */
    int *start[2], *count[2], *tag[2];
    double *pts[2];
    double *capp;       /* cap points of one cut */
    double *dist;       /* distances of the current vertex set, or scratch */
    int *order;         /* plane order */
    double *proj;       /* projected points for the shadow (x, y pairs) */
    int *hull;          /* hull indices */
    double *dA;         /* nvA x ntB distances */
    int *nout;          /* per plane: number of A's vertices outside */
    double *key;        /* per plane of B: how much it faces A (hot path) */
    double *vdist;      /* per vertex of A: distance to the first plane (hot path) */
    int alloc_pts;      /* points allocated (cap_pts may be set lower, for tests) */
    /* the same polyhedron with shared vertices (the fast path): two meshes
     * (double buffering), each vertices (x, y, z) and faces as cycles of
     * vertex indices; scratch for one cut */
    int cap_mv, cap_mf, cap_mi, alloc_mv;
    double *mv[2];
    int *mfs[2], *mfc[2], *mft[2], *mfi[2];
    int mnv[2], mnf[2];
    double *md;         /* per vertex: distance to the cutting plane */
    int *mmap;          /* per vertex: its index in the cut mesh, or -1 */
    int *mlink;         /* per new vertex: the next one along the cap */
    int *medge;         /* crossing edges: (a, b, new vertex) */
    int hslot[PC_HASH], hstamp[PC_HASH], stamp;   /* crossing edge -> its row in medge, for the cut `stamp` */
} work_t;

static void work_free(work_t *w) {
    for (int k = 0; k < 2; k++) { free(w->start[k]); free(w->count[k]); free(w->tag[k]); free(w->pts[k]); }
    free(w->capp); free(w->dist); free(w->order); free(w->proj); free(w->hull); free(w->dA); free(w->nout);
    free(w->key); free(w->vdist);
    for (int k = 0; k < 2; k++) { free(w->mv[k]); free(w->mfs[k]); free(w->mfc[k]); free(w->mft[k]); free(w->mfi[k]); }
    free(w->md); free(w->mmap); free(w->mlink); free(w->medge);
    memset(w, 0, sizeof(*w));
}

/* workspace for polyhedra with at most max_t triangles and max_v vertices */
static int work_init(work_t *w, int max_t, int max_v) {
    memset(w, 0, sizeof(*w));
    int P = 2 * max_t + 12;                     /* polygons: A's triangles + a cap per B plane and box plane */
    long pts = (long)P * (long)(max_t + 12) + 16; /* each convex polygon gains at most one vertex per cut */
    w->cap_poly = P; w->cap_pts = (int)pts; w->alloc_pts = (int)pts;
    for (int k = 0; k < 2; k++) {
        w->start[k] = malloc(sizeof(int) * P); w->count[k] = malloc(sizeof(int) * P);
        w->tag[k] = malloc(sizeof(int) * P); w->pts[k] = malloc(sizeof(double) * 3 * pts);
    }
    w->capp = malloc(sizeof(double) * 3 * (2 * P + 4));
    w->dist = malloc(sizeof(double) * pts);
    w->order = malloc(sizeof(int) * (max_t + 12));
    w->proj = malloc(sizeof(double) * 2 * pts);
    w->hull = malloc(sizeof(int) * (pts + 2));
    w->dA = malloc(sizeof(double) * (long)max_v * (max_t + 1) + 8);
    w->nout = malloc(sizeof(int) * (max_t + 4));
    w->key = malloc(sizeof(double) * (max_t + 4));
    w->vdist = malloc(sizeof(double) * (max_v + 4));
    for (int k = 0; k < 2; k++)
        if (!w->start[k] || !w->count[k] || !w->tag[k] || !w->pts[k]) { work_free(w); return -1; }
    if (!w->capp || !w->dist || !w->order || !w->proj || !w->hull || !w->dA || !w->nout || !w->key || !w->vdist) {
        work_free(w); return -1;
    }
    /* a convex polyhedron with V vertices has at most 2V - 4 faces and 3V - 6
     * edges; a cut adds at most one vertex per edge and one face */
    w->cap_mv = w->alloc_mv = 4 * (max_v + 2 * max_t) + 64;
    w->cap_mf = 3 * max_t + 32;
    w->cap_mi = 6 * w->cap_mv + 64;
    for (int k = 0; k < 2; k++) {
        w->mv[k] = malloc(sizeof(double) * 3 * w->cap_mv);
        w->mfs[k] = malloc(sizeof(int) * w->cap_mf); w->mfc[k] = malloc(sizeof(int) * w->cap_mf);
        w->mft[k] = malloc(sizeof(int) * w->cap_mf); w->mfi[k] = malloc(sizeof(int) * w->cap_mi);
        if (!w->mv[k] || !w->mfs[k] || !w->mfc[k] || !w->mft[k] || !w->mfi[k]) { work_free(w); return -1; }
    }
    w->md = malloc(sizeof(double) * w->cap_mv); w->mmap = malloc(sizeof(int) * w->cap_mv);
    w->mlink = malloc(sizeof(int) * w->cap_mv); w->medge = malloc(sizeof(int) * 3 * w->cap_mv);
    if (!w->md || !w->mmap || !w->mlink || !w->medge) { work_free(w); return -1; }
    return 0;
}

/* ------------------------------------------------------------------ result of one pair */
typedef struct {
    double volume, centroid[3], normal[3], footprint[2], area;
    int status;
    int fallback;       /* the shared-vertex cut gave up and polygons were clipped */
    int kept;           /* 1: from the structure kept from the last step; -1: it no longer held */
} overlap_t;

/* The face structure of a touching pair's overlap, kept for its next step:
 * each vertex by its definition (an A vertex, a B vertex, an A edge cut by a
 * B plane, a B edge cut by an A plane: indices into the two shapes), each
 * face by its plane (tag as in the cuts) and its cycle of vertices. ok = 0:
 * nothing kept (too large, degenerate, or shapes with 255 or more vertices
 * or triangles). */
#define PC_KV 24
#define PC_KF 16
#define PC_KI 80
enum { KV_A = 0, KV_B = 1, KV_AEDGE = 2, KV_BEDGE = 3 };
typedef struct {
    unsigned char ok, nv, nf, ni;
    unsigned char vt[PC_KV], va[PC_KV], vb[PC_KV], vp[PC_KV];   /* type; vertex or edge ends; cutting plane */
    unsigned char fc[PC_KF], ftag[PC_KF];                      /* face size; plane (A triangle, or ntA + B plane) */
    unsigned char fi[PC_KI];
} keep_t;

static void overlap_zero(overlap_t *r) {
    int fb = r->fallback, kp = r->kept;
    memset(r, 0, sizeof(*r));
    r->fallback = fb; r->kept = kp;
    r->centroid[0] = r->centroid[1] = r->centroid[2] = NAN;
    r->normal[0] = r->normal[1] = r->normal[2] = NAN;
}

/* pseudo-angle of (x, y) in [0, 4): monotonic in the polar angle, no trig */
static inline double pseudo_angle(double x, double y) {
    double r = fabs(x) + fabs(y);
    if (r == 0) return 0;
    double p = y / r;                       /* in [-1, 1] */
    return x >= 0 ? (y >= 0 ? p : 4 + p) : 2 - p;
}

/* Order the m cap points (on a plane of unit normal n, outward of the kept
 * part) counter-clockwise seen from n, by their pseudo-angle about their mean
 * (insertion sort: m is small). scratch: 4 doubles per point. */
static void order_cap(double *p, int m, const double *n, double *scratch) {
    double c[3] = {0, 0, 0};
    for (int i = 0; i < m; i++) { c[0] += p[3 * i]; c[1] += p[3 * i + 1]; c[2] += p[3 * i + 2]; }
    c[0] /= m; c[1] /= m; c[2] /= m;
    double u[3], v[3], a[3] = {1, 0, 0};
    if (fabs(n[0]) > 0.6) { a[0] = 0; a[1] = 1; }
    cross3(n, a, u);
    double un = sqrt(dot3(u, u)); u[0] /= un; u[1] /= un; u[2] /= un;
    cross3(n, u, v);
    for (int i = 0; i < m; i++) {
        double d[3] = {p[3 * i] - c[0], p[3 * i + 1] - c[1], p[3 * i + 2] - c[2]};
        double key = pseudo_angle(dot3(d, u), dot3(d, v));
        int j = i;
        while (j > 0 && scratch[4 * (j - 1)] > key) { memcpy(scratch + 4 * j, scratch + 4 * (j - 1), 4 * sizeof(double)); j--; }
        scratch[4 * j] = key; scratch[4 * j + 1] = p[3 * i]; scratch[4 * j + 2] = p[3 * i + 1]; scratch[4 * j + 3] = p[3 * i + 2];
    }
    for (int i = 0; i < m; i++) { p[3 * i] = scratch[4 * i + 1]; p[3 * i + 1] = scratch[4 * i + 2]; p[3 * i + 2] = scratch[4 * i + 3]; }
}

/* shadow of the point set (npts points, 3D) on the plane normal to n:
 * area, and widths along the principal axes of the shadow polygon */
static void shadow(const double *pts, int npts, const double *n, work_t *w, double *area, double *fp) {
    double u[3], v[3], a[3] = {1, 0, 0};
    if (fabs(n[0]) > 0.6) { a[0] = 0; a[1] = 1; }
    cross3(n, a, u);
    double un = sqrt(dot3(u, u)); u[0] /= un; u[1] /= un; u[2] /= un;
    cross3(n, u, v);
    double *P = w->proj;
    for (int i = 0; i < npts; i++) {              /* project, insertion-sorted by (x, y) */
        double x = dot3(pts + 3 * i, u), y = dot3(pts + 3 * i, v);
        int j = i;
        while (j > 0 && (P[2 * (j - 1)] > x || (P[2 * (j - 1)] == x && P[2 * (j - 1) + 1] > y))) {
            P[2 * j] = P[2 * (j - 1)]; P[2 * j + 1] = P[2 * (j - 1) + 1]; j--;
        }
        P[2 * j] = x; P[2 * j + 1] = y;
    }
    /* Andrew's monotone chain */
    int *H = w->hull, k = 0;
    for (int i = 0; i < npts; i++) {
        while (k >= 2) {
            const double *o = P + 2 * H[k - 2], *p = P + 2 * H[k - 1], *q = P + 2 * i;
            if ((p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0]) <= 0) k--; else break;
        }
        H[k++] = i;
    }
    for (int i = npts - 2, lo = k + 1; i >= 0; i--) {
        while (k >= lo) {
            const double *o = P + 2 * H[k - 2], *p = P + 2 * H[k - 1], *q = P + 2 * i;
            if ((p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0]) <= 0) k--; else break;
        }
        H[k++] = i;
    }
    int m = k - 1;                      /* last point repeats the first */
    if (m < 3) {                        /* segment or point: widths from the points */
        double ext = 0;
        for (int i = 0; i < npts; i++)
            for (int j = i + 1; j < npts; j++) {
                double dx = P[2 * i] - P[2 * j], dy = P[2 * i + 1] - P[2 * j + 1];
                double e = sqrt(dx * dx + dy * dy);
                if (e > ext) ext = e;
            }
        *area = 0; fp[0] = ext; fp[1] = 0;
        return;
    }
    /* area, centroid and second moments of the polygon (origin at its first vertex) */
    const double *o = P + 2 * H[0];
    double A2 = 0, cx = 0, cy = 0, ixx = 0, iyy = 0, ixy = 0;
    for (int i = 0; i < m; i++) {
        const double *p = P + 2 * H[i], *q = P + 2 * H[i + 1];
        double x0 = p[0] - o[0], y0 = p[1] - o[1], x1 = q[0] - o[0], y1 = q[1] - o[1];
        double cr = x0 * y1 - x1 * y0;
        A2 += cr;
        cx += (x0 + x1) * cr; cy += (y0 + y1) * cr;
        ixx += (x0 * x0 + x0 * x1 + x1 * x1) * cr;   /* integral of x^2 (times 12) */
        iyy += (y0 * y0 + y0 * y1 + y1 * y1) * cr;
        ixy += (x0 * y1 + 2 * x0 * y0 + 2 * x1 * y1 + x1 * y0) * cr;
    }
    double A = 0.5 * A2;
    *area = fabs(A);
    double mx = 0, my = 0;
    if (A != 0) { mx = cx / (6 * A); my = cy / (6 * A); }
    double Sxx = ixx / 12 - A * mx * mx, Syy = iyy / 12 - A * my * my, Sxy = ixy / 24 - A * mx * my;
    /* principal axis of the largest second moment of the x-distribution:
     * the covariance [[Sxx, Sxy], [Sxy, Syy]] (integrals of x^2 etc.) */
    double th = 0.5 * atan2(2 * Sxy, Sxx - Syy);
    double e1[2] = {cos(th), sin(th)}, e2[2] = {-sin(th), cos(th)};
    double lo1 = INFINITY, hi1 = -INFINITY, lo2 = INFINITY, hi2 = -INFINITY;
    for (int i = 0; i < m; i++) {
        const double *p = P + 2 * H[i];
        double s1 = p[0] * e1[0] + p[1] * e1[1], s2 = p[0] * e2[0] + p[1] * e2[1];
        lo1 = s1 < lo1 ? s1 : lo1; hi1 = s1 > hi1 ? s1 : hi1;
        lo2 = s2 < lo2 ? s2 : lo2; hi2 = s2 > hi2 ? s2 : hi2;
    }
    double w1 = hi1 - lo1, w2 = hi2 - lo2;
    if (w1 >= w2) { fp[0] = w1; fp[1] = w2; } else { fp[0] = w2; fp[1] = w1; }
}

/* From the sums over the faces (6 V, the centroid moments about o, S_A and
 * the total face area): volume, centroid, normal, and the shadow of the
 * npts points. */
static void finish_overlap(work_t *w, double V6, const double *C, const double *o, const double *SA, double Stot,
                           const double *xB_minus_xA, const double *spts, int npts, int want_shadow, overlap_t *r) {
    double V = V6 / 6.0;
    if (!(V > 0)) { overlap_zero(r); return; }
    r->volume = V;
    r->centroid[0] = o[0] + C[0] / (4 * V6); r->centroid[1] = o[1] + C[1] / (4 * V6); r->centroid[2] = o[2] + C[2] / (4 * V6);
    double s = sqrt(dot3(SA, SA));
    r->status = PC_OK;
    if (s > 1e-9 * Stot && s > 0) {
        r->normal[0] = SA[0] / s; r->normal[1] = SA[1] / s; r->normal[2] = SA[2] / s;
    } else {
        /* B inside A or identical poses: no net area on A's side; fall back
         * to the line of centres, else +z */
        r->status = PC_DEGENERATE_NORMAL;
        double l = xB_minus_xA ? sqrt(dot3(xB_minus_xA, xB_minus_xA)) : 0;
        if (l > 0) { r->normal[0] = xB_minus_xA[0] / l; r->normal[1] = xB_minus_xA[1] / l; r->normal[2] = xB_minus_xA[2] / l; }
        else { r->normal[0] = 0; r->normal[1] = 0; r->normal[2] = 1; }
    }
    /* the shadow, from the points; it does not enter the contact law, so the
     * engine computes it only for the contacts it reports (NaN until then) */
    if (!want_shadow) {
        r->area = NAN; r->footprint[0] = r->footprint[1] = NAN;
        return;
    }
    shadow(spts, npts, r->normal, w, &r->area, r->footprint);
}


/* Finish: volume, centroid, S_A and the shadow from the polygon set. */
static void integrate(work_t *w, int buf, int np, int ntA, const double *nA, const double *xB_minus_xA,
                      int want_shadow, overlap_t *r) {
    int *start = w->start[buf], *count = w->count[buf], *tag = w->tag[buf];
    double *pts = w->pts[buf];
    if (np == 0) { overlap_zero(r); return; }
    const double *o = pts + 3 * start[0];
    double V6 = 0, C[3] = {0, 0, 0}, SA[3] = {0, 0, 0}, Stot = 0;
    for (int f = 0; f < np; f++) {
        const double *p0 = pts + 3 * start[f];
        double av[3] = {0, 0, 0};
        for (int i = 1; i + 1 < count[f]; i++) {
            const double *p1 = pts + 3 * (start[f] + i), *p2 = pts + 3 * (start[f] + i + 1);
            double a[3] = {p0[0] - o[0], p0[1] - o[1], p0[2] - o[2]};
            double b[3] = {p1[0] - o[0], p1[1] - o[1], p1[2] - o[2]};
            double c[3] = {p2[0] - o[0], p2[1] - o[1], p2[2] - o[2]};
            double bc[3];
            cross3(b, c, bc);
            double v6 = dot3(a, bc);
            V6 += v6;
            C[0] += v6 * (a[0] + b[0] + c[0]); C[1] += v6 * (a[1] + b[1] + c[1]); C[2] += v6 * (a[2] + b[2] + c[2]);
            double e1[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
            double e2[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
            double t[3];
            cross3(e1, e2, t);
            av[0] += 0.5 * t[0]; av[1] += 0.5 * t[1]; av[2] += 0.5 * t[2];
        }
        Stot += sqrt(dot3(av, av));
        if (tag[f] >= 0 && tag[f] < ntA) {   /* a face on A's surface: area x A's unit normal */
            const double *nf = nA + 3 * tag[f];
            double a = dot3(av, nf);
            SA[0] += a * nf[0]; SA[1] += a * nf[1]; SA[2] += a * nf[2];
        }
    }
    int first = start[0];
    int last = start[np - 1] + count[np - 1];
    finish_overlap(w, V6, C, o, SA, Stot, xB_minus_xA, pts + 3 * first, last - first, want_shadow, r);
}

/* Clip the current polygon set (buffer buf, np polygons) by the plane
 * n.x <= h (tag = cap tag). A point is outside when n.x - h > eps, a
 * round-off tolerance: a plane that (nearly) contains a face or an earlier
 * cap must not cut it into slivers of either sign and a second cap. Returns
 * the new polygon count in buffer 1-buf, or -1 when no point lies outside
 * (the set is unchanged, still in buf). */
static int clip_plane(work_t *w, int buf, int np, const double *n, double h, int captag, double eps,
                      int *overflow) {
    int *s0 = w->start[buf], *c0 = w->count[buf], *t0 = w->tag[buf];
    double *p0 = w->pts[buf];
    /* the polygons are contiguous in the buffer: one pass gives every
     * point's distance (kept for the cut) and decides whether any is outside */
    int first = s0[0], tot = s0[np - 1] + c0[np - 1] - first, any = 0;
    double *dist = w->dist;
    {
        const double *q0 = p0 + 3 * first;
        for (int i = 0; i < tot; i++) { dist[i] = dot3(q0 + 3 * i, n) - h; any |= dist[i] > eps; }
        if (!any) return -1;
    }
    int *s1 = w->start[1 - buf], *c1 = w->count[1 - buf], *t1 = w->tag[1 - buf];
    double *p1 = w->pts[1 - buf];
    double *cap = w->capp;
    int ncap = 0, out = 0, q = 0;
    for (int f = 0; f < np; f++) {
        int st = s0[f], cn = c0[f];
        double *P = p0 + 3 * st;
        const double *d = dist + (st - first);
        int nin = 0;
        for (int i = 0; i < cn; i++) nin += d[i] <= eps;
        if (nin == 0) continue;                                     /* all outside */
        if (q + cn + 1 > w->cap_pts || out + 2 > w->cap_poly) { *overflow = 1; return 0; }
        s1[out] = q; t1[out] = t0[f];
        if (nin == cn) {                                            /* all inside: copy */
            memcpy(p1 + 3 * q, P, sizeof(double) * 3 * cn);
            q += cn; c1[out++] = cn;
            continue;
        }
        int m = 0;
        for (int i = 0; i < cn; i++) {
            int j = (i + 1 == cn) ? 0 : i + 1;
            const double *a = P + 3 * i, *b = P + 3 * j;
            double da = d[i], db = d[j];
            int ina = da <= eps, inb = db <= eps;
            if (ina) { memcpy(p1 + 3 * (q + m), a, 3 * sizeof(double)); m++; }
            if (ina != inb) {
                /* canonical: from the inside end to the outside end */
                const double *pi = ina ? a : b, *po = ina ? b : a;
                double di = ina ? da : db, dout = ina ? db : da;
                double t = di / (di - dout);
                t = t < 0 ? 0 : (t > 1 ? 1 : t);
                double x[3] = {pi[0] + t * (po[0] - pi[0]), pi[1] + t * (po[1] - pi[1]), pi[2] + t * (po[2] - pi[2])};
                memcpy(p1 + 3 * (q + m), x, 3 * sizeof(double)); m++;
                memcpy(cap + 3 * ncap, x, 3 * sizeof(double)); ncap++;
            }
        }
        if (m >= 3) { c1[out++] = m; q += m; }
    }
    if (ncap >= 3 && out > 0) {
        if (q + ncap > w->cap_pts || out + 1 > w->cap_poly) { *overflow = 1; return 0; }
        order_cap(cap, ncap, n, w->proj);
        /* A cut edge shared by two polygons gives the same point twice (cut
         * from its inside end, so the same bits): keep one. A repeated point
         * adds exact zeros to every integral and nothing to any hull. */
        int m = 1;
        for (int i = 1; i < ncap; i++) {
            const double *a = cap + 3 * (m - 1), *b = cap + 3 * i;
            if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) continue;
            if (m != i) memcpy(cap + 3 * m, b, 3 * sizeof(double));
            m++;
        }
        ncap = m;
        memcpy(p1 + 3 * q, cap, sizeof(double) * 3 * ncap);
        s1[out] = q; c1[out] = ncap; t1[out] = captag; out++; q += ncap;
    }
    return out;
}

/* centre (mean of the points) and radius of a sphere holding the polygons */
static void bounding_sphere(const work_t *w, int buf, int np, double *c, double *r) {
    const double *q0 = w->pts[buf] + 3 * w->start[buf][0];
    int tot = w->start[buf][np - 1] + w->count[buf][np - 1] - w->start[buf][0];
    c[0] = c[1] = c[2] = 0;
    for (int i = 0; i < tot; i++) { c[0] += q0[3 * i]; c[1] += q0[3 * i + 1]; c[2] += q0[3 * i + 2]; }
    c[0] /= tot; c[1] /= tot; c[2] /= tot;
    double m = 0;
    for (int i = 0; i < tot; i++) {
        double d[3] = {q0[3 * i] - c[0], q0[3 * i + 1] - c[1], q0[3 * i + 2] - c[2]};
        double l = dot3(d, d);
        if (l > m) m = l;
    }
    *r = sqrt(m) * (1 + 1e-12) + 1e-300;
}

/* ------------------------------------------------------------------ shared-vertex clipping (fast path) */
/* The polyhedron A (its vertices and triangles) as mesh 0. */
static void mesh_start(work_t *w, const posed_t *A) {
    memcpy(w->mv[0], A->v, sizeof(double) * 3 * A->nv);
    if (A->nf > 0) {                                   /* the polygonal faces */
        memcpy(w->mfs[0], A->fs, sizeof(int) * A->nf); memcpy(w->mfc[0], A->fc, sizeof(int) * A->nf);
        memcpy(w->mft[0], A->ftag, sizeof(int) * A->nf);
        memcpy(w->mfi[0], A->fi, sizeof(int) * (A->fs[A->nf - 1] + A->fc[A->nf - 1]));
        w->mnv[0] = A->nv; w->mnf[0] = A->nf;
        return;
    }
    for (int f = 0; f < A->nt; f++) {
        w->mfs[0][f] = 3 * f; w->mfc[0][f] = 3; w->mft[0][f] = f;
        w->mfi[0][3 * f] = A->t[3 * f]; w->mfi[0][3 * f + 1] = A->t[3 * f + 1]; w->mfi[0][3 * f + 2] = A->t[3 * f + 2];
    }
    w->mnv[0] = A->nv; w->mnf[0] = A->nt;
}

/* Cut mesh buf by the plane n.x <= h (outside: n.x - h > eps, as
 * clip_plane). Each vertex's distance is computed once; a crossing edge gets
 * one new vertex, cut from its inside end as clip_plane does (the same
 * bits), shared by its two faces; the cap is traced, not sorted: a cut face
 * runs inside ... X (leaves) ... Y (re-enters) ..., and the cap, which
 * shares the segment X-Y, runs Y -> X. Returns -1 when nothing is outside
 * (unchanged), else the face count of mesh 1 - buf (0: nothing left), or -2
 * when the cut does not look like a convex one (a face crossed other than
 * twice, a cap that does not close, a full workspace): the caller then
 * clips by polygons. */
static int mesh_clip(work_t *w, int buf, const double *n, double h, int captag, double eps) {
    int nv = w->mnv[buf], nf = w->mnf[buf];
    const double *V = w->mv[buf];
    const int *fs = w->mfs[buf], *fc = w->mfc[buf], *ft = w->mft[buf], *fi = w->mfi[buf];
    double *d = w->md;
    int *map = w->mmap, any = 0, nin = 0;
    for (int i = 0; i < nv; i++) { d[i] = dot3(V + 3 * i, n) - h; int out = d[i] > eps; any |= out; nin += !out; }
    if (!any) return -1;
    int o = 1 - buf;
    double *V2 = w->mv[o];
    int *fs2 = w->mfs[o], *fc2 = w->mfc[o], *ft2 = w->mft[o], *fi2 = w->mfi[o];
    if (nin == 0) { w->mnv[o] = 0; w->mnf[o] = 0; return 0; }
    int nv2 = 0;
    for (int i = 0; i < nv; i++) {
        if (d[i] > eps) { map[i] = -1; continue; }
        memcpy(V2 + 3 * nv2, V + 3 * i, 3 * sizeof(double));
        map[i] = nv2++;
    }
    int first_new = nv2, ne = 0, nf2 = 0, ni2 = 0, *E = w->medge, *link = w->mlink;
    int stamp = ++w->stamp;
    if (stamp == 0x7fffffff) { memset(w->hstamp, 0, sizeof(w->hstamp)); w->stamp = stamp = 1; }
    for (int f = 0; f < nf; f++) {
        int st = fs[f], cn = fc[f], kin = 0;
        for (int i = 0; i < cn; i++) kin += map[fi[st + i]] >= 0;
        if (kin == 0) continue;                                     /* wholly outside */
        if (nf2 + 2 > w->cap_mf || ni2 + cn + 2 > w->cap_mi) return -2;
        fs2[nf2] = ni2; ft2[nf2] = ft[f];
        if (kin == cn) {                                            /* wholly inside */
            for (int i = 0; i < cn; i++) fi2[ni2++] = map[fi[st + i]];
            fc2[nf2++] = cn;
            continue;
        }
        int X = -1, Y = -1, cross = 0, m = 0;
        for (int i = 0; i < cn; i++) {
            int a = fi[st + i], b = fi[st + (i + 1 == cn ? 0 : i + 1)];
            int ina = map[a] >= 0, inb = map[b] >= 0;
            if (ina) { fi2[ni2 + m++] = map[a]; }
            if (ina == inb) continue;
            int lo = a < b ? a : b, hi = a < b ? b : a, k = -1;
            unsigned slot = ((unsigned)lo * 2654435761u ^ (unsigned)hi * 40503u) & (PC_HASH - 1);
            while (w->hstamp[slot] == stamp) {             /* open addressing: a filled slot of this cut */
                const int *e = E + 3 * w->hslot[slot];
                if (e[0] == lo && e[1] == hi) { k = e[2]; break; }
                slot = (slot + 1) & (PC_HASH - 1);
            }
            if (k < 0) {
                if (nv2 + 1 > w->cap_mv || ne + 1 >= PC_HASH / 2) return -2;
                w->hstamp[slot] = stamp; w->hslot[slot] = ne;
                int pi = ina ? a : b, po = ina ? b : a;               /* from the inside end, as clip_plane */
                double di = d[pi], dout = d[po];
                double t = di / (di - dout);
                t = t < 0 ? 0 : (t > 1 ? 1 : t);
                const double *P = V + 3 * pi, *Q = V + 3 * po;
                double *x = V2 + 3 * nv2;
                x[0] = P[0] + t * (Q[0] - P[0]); x[1] = P[1] + t * (Q[1] - P[1]); x[2] = P[2] + t * (Q[2] - P[2]);
                link[nv2 - first_new] = -1;
                k = nv2++;
                E[3 * ne] = lo; E[3 * ne + 1] = hi; E[3 * ne + 2] = k; ne++;
            }
            fi2[ni2 + m++] = k;
            if (ina) X = k; else Y = k;
            cross++;
        }
        if (cross != 2 || X < 0 || Y < 0) return -2;
        if (link[Y - first_new] >= 0) return -2;                   /* two faces re-enter at one point */
        link[Y - first_new] = X;
        if (m >= 3) { fc2[nf2++] = m; ni2 += m; }
    }
    int nnew = nv2 - first_new;
    if (nnew >= 3) {                                                /* the cap, traced */
        if (nf2 + 1 > w->cap_mf || ni2 + nnew > w->cap_mi) return -2;
        int v = first_new, m = 0;
        do {
            fi2[ni2 + m++] = v;
            v = link[v - first_new];
            if (v < 0 || m > nnew) return -2;
        } while (v != first_new);
        if (m != nnew) return -2;                                  /* more than one loop */
        fs2[nf2] = ni2; fc2[nf2] = m; ft2[nf2] = captag; nf2++; ni2 += m;
    }
    w->mnv[o] = nv2; w->mnf[o] = nf2;
    return nf2;
}

/* centre (mean of the vertices) and radius of a sphere holding mesh buf */
static void mesh_sphere(const work_t *w, int buf, double *c, double *r) {
    const double *V = w->mv[buf];
    int nv = w->mnv[buf];
    c[0] = c[1] = c[2] = 0;
    for (int i = 0; i < nv; i++) { c[0] += V[3 * i]; c[1] += V[3 * i + 1]; c[2] += V[3 * i + 2]; }
    c[0] /= nv; c[1] /= nv; c[2] /= nv;
    double m = 0;
    for (int i = 0; i < nv; i++) {
        double e[3] = {V[3 * i] - c[0], V[3 * i + 1] - c[1], V[3 * i + 2] - c[2]};
        double l = dot3(e, e);
        if (l > m) m = l;
    }
    *r = sqrt(m) * (1 + 1e-12) + 1e-300;
}

/* integrate() for mesh buf: volume, centroid, S_A and normal, the shadow
 * from the (unique) vertices */
static void mesh_integrate(work_t *w, int buf, int ntA, const double *nA, const double *xB_minus_xA,
                           int want_shadow, overlap_t *r) {
    int nf = w->mnf[buf];
    const double *V = w->mv[buf];
    const int *fs = w->mfs[buf], *fc = w->mfc[buf], *ft = w->mft[buf], *fi = w->mfi[buf];
    if (nf == 0) { overlap_zero(r); return; }
    const double *o = V + 3 * fi[fs[0]];
    double V6 = 0, C[3] = {0, 0, 0}, SA[3] = {0, 0, 0}, Stot = 0, L1 = 0, *an2 = w->md;
    for (int f = 0; f < nf; f++) {
        const int *ix = fi + fs[f];
        const double *p0 = V + 3 * ix[0];
        double av[3] = {0, 0, 0};
        for (int i = 1; i + 1 < fc[f]; i++) {
            const double *p1 = V + 3 * ix[i], *p2 = V + 3 * ix[i + 1];
            double a[3] = {p0[0] - o[0], p0[1] - o[1], p0[2] - o[2]};
            double b[3] = {p1[0] - o[0], p1[1] - o[1], p1[2] - o[2]};
            double c[3] = {p2[0] - o[0], p2[1] - o[1], p2[2] - o[2]};
            double bc[3];
            cross3(b, c, bc);
            double v6 = dot3(a, bc);
            V6 += v6;
            C[0] += v6 * (a[0] + b[0] + c[0]); C[1] += v6 * (a[1] + b[1] + c[1]); C[2] += v6 * (a[2] + b[2] + c[2]);
            double e1[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
            double e2[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
            double t[3];
            cross3(e1, e2, t);
            av[0] += 0.5 * t[0]; av[1] += 0.5 * t[1]; av[2] += 0.5 * t[2];
        }
        an2[f] = dot3(av, av);
        L1 += fabs(av[0]) + fabs(av[1]) + fabs(av[2]);
        if (ft[f] >= 0 && ft[f] < ntA) {
            const double *nn = nA + 3 * ft[f];
            double a = dot3(av, nn);
            SA[0] += a * nn[0]; SA[1] += a * nn[1]; SA[2] += a * nn[2];
        }
    }
    /* Stot, the sum of the faces' areas, enters only finish_overlap's test
     * |S_A| > 1e-9 Stot; the sum of their 1-norms bounds it from above, so
     * when |S_A| clears that bound the test is decided, and the square roots
     * are taken only when it does not (the same sum as integrate's) */
    double s = sqrt(dot3(SA, SA));
    if (s > 1e-9 * L1 * (1 + 1e-12)) Stot = L1;
    else for (int f = 0; f < nf; f++) Stot += sqrt(an2[f]);
    finish_overlap(w, V6, C, o, SA, Stot, xB_minus_xA, V, w->mnv[buf], want_shadow, r);
}

/* The vertex shared by every triangle in tri[0..n) of shape S (triangles
 * t as vertex triples), or -1 when none or several. */
static int common_vertex(const int *t, const int *tri, int n) {
    int found = -1;
    for (int c = 0; c < 3; c++) {
        int v = t[3 * tri[0] + c], all = 1;
        for (int k = 1; k < n && all; k++) all = t[3 * tri[k]] == v || t[3 * tri[k] + 1] == v || t[3 * tri[k] + 2] == v;
        if (all) { if (found >= 0) return -1; found = v; }
    }
    return found;
}

/* The edge (two vertices) shared by triangles a and b, or 0 when not one. */
static int common_edge(const int *t, int a, int b, int *u, int *v) {
    int m = 0, e[3];
    for (int c = 0; c < 3; c++) {
        int x = t[3 * a + c];
        if (t[3 * b] == x || t[3 * b + 1] == x || t[3 * b + 2] == x) e[m++] = x;
    }
    if (m != 2) return 0;
    *u = e[0]; *v = e[1];
    return 1;
}

/* The same on a shape with coplanar triangles, whose cuts are by planes
 * (one triangle of each, the others skipped as duplicates): the vertex on
 * every plane of tri[0..n), or the edge on both planes a and b, from the
 * vertex sets of the planes' whole faces (pmask), or -1 / 0 when not one. */
static int plane_vertex(const uint64_t *pmask, const int *tri, int n) {
    int found = -1;
    for (int q = 0; q < PC_MASK_WORDS; q++) {
        uint64_t m = pmask[PC_MASK_WORDS * tri[0] + q];
        for (int k = 1; k < n; k++) m &= pmask[PC_MASK_WORDS * tri[k] + q];
        if (!m) continue;
        if (found >= 0 || (m & (m - 1))) return -1;
        found = 64 * q + __builtin_ctzll(m);
    }
    return found;
}

static int plane_edge(const uint64_t *pmask, int a, int b, int *u, int *v) {
    int e[2], m = 0;
    for (int q = 0; q < PC_MASK_WORDS; q++) {
        uint64_t x = pmask[PC_MASK_WORDS * a + q] & pmask[PC_MASK_WORDS * b + q];
        while (x) {
            if (m == 2) return 0;
            e[m++] = 64 * q + __builtin_ctzll(x);
            x &= x - 1;
        }
    }
    if (m != 2) return 0;
    *u = e[0]; *v = e[1];
    return 1;
}

/* Label mesh buf (A n B after the cuts) for the next step: each vertex by
 * the planes of the faces around it. A's faces are its triangles (pieces of
 * them), coplanar ones included: a point cut on the diagonal two coplanar
 * triangles share lies on that segment of A, and is labelled by it. B's
 * faces are its planes (the cuts skip a plane's other triangles), whose
 * vertices and edges are looked up on the planes' whole faces when B has
 * coplanar triangles. */
static void keep_structure(const work_t *w, int buf, const posed_t *A, const posed_t *B, keep_t *K) {
    K->ok = 0;
    int nv = w->mnv[buf], nf = w->mnf[buf], ntA = A->nt;
    if (nv > PC_KV || nf > PC_KF || A->nv >= 255 || B->nv >= 255 || ntA + B->nt >= 255) return;
    const int *fs = w->mfs[buf], *fc = w->mfc[buf], *ft = w->mft[buf], *fi = w->mfi[buf];
    int inc[PC_KV][8], ninc[PC_KV], ni = 0;
    memset(ninc, 0, sizeof(ninc));
    for (int f = 0; f < nf; f++) {
        if (ft[f] < 0 || fc[f] < 3) return;
        if (ft[f] >= ntA && B->dup && B->dup[ft[f] - ntA]) return;   /* not a cut's plane (never: they skip these) */
        for (int i = 0; i < fc[f]; i++) {
            int v = fi[fs[f] + i];
            if (ninc[v] == 8) return;
            inc[v][ninc[v]++] = ft[f];
        }
        ni += fc[f];
    }
    if (ni > PC_KI) return;
    for (int v = 0; v < nv; v++) {
        int ta[8], tb[8], na = 0, nb = 0;
        for (int k = 0; k < ninc[v]; k++) { if (inc[v][k] < ntA) ta[na++] = inc[v][k]; else tb[nb++] = inc[v][k] - ntA; }
        int x, y;
        if (nb == 0 && na >= 3) {
            if ((x = A->nf ? plane_vertex(A->pmask, ta, na) : common_vertex(A->t, ta, na)) < 0) return;
            K->vt[v] = KV_A; K->va[v] = (unsigned char)x;
        } else if (na == 0 && nb >= 3) {
            if ((x = B->pmask ? plane_vertex(B->pmask, tb, nb) : common_vertex(B->t, tb, nb)) < 0) return;
            K->vt[v] = KV_B; K->va[v] = (unsigned char)x;
        } else if (na == 2 && nb == 1) {
            if (!(A->nf ? plane_edge(A->pmask, ta[0], ta[1], &x, &y) : common_edge(A->t, ta[0], ta[1], &x, &y))) return;
            K->vt[v] = KV_AEDGE; K->va[v] = (unsigned char)x; K->vb[v] = (unsigned char)y; K->vp[v] = (unsigned char)tb[0];
        } else if (na == 1 && nb == 2) {
            if (!(B->pmask ? plane_edge(B->pmask, tb[0], tb[1], &x, &y) : common_edge(B->t, tb[0], tb[1], &x, &y))) return;
            K->vt[v] = KV_BEDGE; K->va[v] = (unsigned char)x; K->vb[v] = (unsigned char)y; K->vp[v] = (unsigned char)ta[0];
        } else {
            return;                                               /* four planes or more at a point: degenerate */
        }
    }
    for (int f = 0, q = 0; f < nf; f++) {
        K->fc[f] = (unsigned char)fc[f]; K->ftag[f] = (unsigned char)ft[f];
        for (int i = 0; i < fc[f]; i++) K->fi[q++] = (unsigned char)fi[fs[f] + i];
    }
    K->nv = (unsigned char)nv; K->nf = (unsigned char)nf; K->ni = (unsigned char)ni;
    K->ok = 1;
}

/* The point where the segment p (inside, distance dp) - q (outside, dq)
 * meets the plane, from the inside end as clip_plane. */
static inline void cut_point(const double *p, double dp, const double *q, double dq, double *x) {
    double t = dp / (dp - dq);
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    x[0] = p[0] + t * (q[0] - p[0]); x[1] = p[1] + t * (q[1] - p[1]); x[2] = p[2] + t * (q[2] - p[2]);
}

/* The overlap from the kept structure, when it still holds (see
 * overlap_pair): its vertices from their definitions, checked (i) each cut
 * edge still crosses its plane, (ii) every vertex lies inside every plane of
 * the other grain (it lies in its own by construction), (iii) every face is still convex and turns the way its plane's
 * normal says. Then the structure bounds a convex polytope inside A n B
 * whose faces' half-spaces hold A n B: it is A n B. Returns 0 (r set) or -1
 * (the structure no longer holds: cut). The vertices and faces go to mesh 0. */
static int overlap_kept(const posed_t *A, const posed_t *B, const double *dAB, work_t *w, overlap_t *r,
                        const keep_t *K, int want_shadow, double eps) {
    int ntA = A->nt;
    double *V = w->mv[0];
    for (int v = 0; v < K->nv; v++) {
        double *x = V + 3 * v;
        int t = K->vt[v];
        if (t == KV_A) { memcpy(x, A->v + 3 * K->va[v], 3 * sizeof(double)); continue; }
        if (t == KV_B) { memcpy(x, B->v + 3 * K->va[v], 3 * sizeof(double)); continue; }
        const posed_t *E = t == KV_AEDGE ? A : B, *P = t == KV_AEDGE ? B : A;
        const double *n = plane_n(P, K->vp[v]), *pu = E->v + 3 * K->va[v], *pv = E->v + 3 * K->vb[v];
        double h = plane_h(P, K->vp[v]), du = dot3(pu, n) - h, dv = dot3(pv, n) - h;
        int iu = du <= eps, iv = dv <= eps;
        if (iu == iv) return -1;                                   /* (i) */
        if (iu) cut_point(pu, du, pv, dv, x); else cut_point(pv, dv, pu, du, x);
    }
    /* (ii) A's vertices and the points on A's edges lie in A by
     * construction (convex combinations of A's vertices), so A's planes are
     * tested on the others only (B's vertices and the points on B's edges),
     * and the other way round; each group within its own sphere about the
     * overlap's centre. */
    double sc[3], sr, rg[2] = {0, 0};
    int grp[2][PC_KV], ng[2] = {0, 0};
    w->mnv[0] = K->nv;
    mesh_sphere(w, 0, sc, &sr);
    for (int v = 0; v < K->nv; v++) {
        int g = K->vt[v] == KV_A || K->vt[v] == KV_AEDGE;          /* 1: in A, test against B's planes */
        const double *x = V + 3 * v;
        double e[3] = {x[0] - sc[0], x[1] - sc[1], x[2] - sc[2]}, l = dot3(e, e);
        if (l > rg[g]) rg[g] = l;
        grp[g][ng[g]++] = v;
    }
    for (int g = 0; g < 2; g++) {
        const posed_t *P = g ? B : A;
        double r = sqrt(rg[g]) * (1 + 1e-12) + 1e-300;
        if (ng[g] == 0) continue;
        int np = P->nf ? P->nf : P->nt;                            /* its planes: one per face, in triangle order */
        for (int f = 0; f < np; f++) {
            int k = P->nf ? P->ftag[f] : f;
            if (P->dup && P->dup[k]) continue;                     /* the plane of an earlier triangle, as in the cuts */
            const double *n = plane_n(P, k);
            double h = plane_h(P, k);
            if (dot3(n, sc) - h + r <= eps) continue;
            for (int i = 0; i < ng[g]; i++) if (dot3(V + 3 * grp[g][i], n) - h > eps) return -1;
        }
    }
    for (int f = 0, q = 0; f < K->nf; f++) {                        /* (iii), and mesh 0's faces */
        int m = K->fc[f], tag = K->ftag[f];
        const double *n = tag < ntA ? plane_n(A, tag) : plane_n(B, tag - ntA);
        w->mfs[0][f] = q; w->mfc[0][f] = m; w->mft[0][f] = tag;
        for (int i = 0; i < m; i++) {
            const double *a = V + 3 * K->fi[q + (i ? i - 1 : m - 1)], *b = V + 3 * K->fi[q + i];
            const double *c = V + 3 * K->fi[q + (i + 1 < m ? i + 1 : 0)];
            double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - b[0], c[1] - b[1], c[2] - b[2]}, x[3];
            cross3(e1, e2, x);
            double t = dot3(x, n);                                 /* the lengths only when it turns the wrong way */
            if (t < 0 && t < -eps * (sqrt(dot3(e1, e1)) + sqrt(dot3(e2, e2)))) return -1;
            w->mfi[0][q + i] = K->fi[q + i];
        }
        q += m;
    }
    w->mnf[0] = K->nf;
    mesh_integrate(w, 0, ntA, A->n, dAB, want_shadow, r);
    return 0;
}

/* Separation by a face: the number nout[k] of A's vertices outside each
 * plane k of B (0 for a duplicate, the same plane as an earlier triangle's),
 * and whether A lies wholly outside a plane of B (sep_axis -n_k, from A to
 * B) or B wholly outside a plane of A (sep_axis n_k): 1, else 0. */
static int face_separation(const posed_t *A, const posed_t *B, int *nout, double *sep_axis) {
    for (int k = 0; k < B->nt; k++) {
        if (B->dup && B->dup[k]) { nout[k] = 0; continue; }
        const double *n = B->n + 3 * k;
        double h = B->h[k];
        int c = 0;
        for (int i = 0; i < A->nv; i++) c += dot3(A->v + 3 * i, n) - h > 0;
        if (c == A->nv) {
            if (sep_axis) { sep_axis[0] = -n[0]; sep_axis[1] = -n[1]; sep_axis[2] = -n[2]; }
            return 1;
        }
        nout[k] = c;
    }
    for (int k = 0; k < A->nt; k++) {
        if (A->dup && A->dup[k]) continue;
        const double *n = A->n + 3 * k;
        double h = A->h[k];
        int c = 0;
        for (int i = 0; i < B->nv; i++) c += dot3(B->v + 3 * i, n) - h > 0;
        if (c == B->nv) {
            if (sep_axis) memcpy(sep_axis, n, 3 * sizeof(double));
            return 1;
        }
    }
    return 0;
}

/* The overlap by shared-vertex cuts (the fast path): the same planes in the
 * same order as overlap_pair's culled path, each vertex and each crossing
 * point computed once. The vertices are those of the polygon path to the bit
 * (same formulas, same inputs); the faces are cut into the same polygons but
 * the caps start at another vertex, so volumes agree to round-off. Returns
 * 0, or -2 when a cut gave up (the caller clips polygons). */
static int overlap_mesh(const posed_t *A, const posed_t *B, const double *dAB, work_t *w, overlap_t *r,
                        double *sep_axis, int hot, int want_shadow, double eps, keep_t *keep) {
    int ntB = B->nt, *ord = w->order, m = 0, buf = 0, nf;
    double sc[3] = {0, 0, 0}, sr = INFINITY;
    mesh_start(w, A);
    nf = A->nt;
    if (hot && dAB) {
        double *key = w->key;
        int k0 = -1;
        for (int k = 0; k < ntB; k++) {
            key[k] = -dot3(B->n + 3 * k, dAB);
            if (!(B->dup && B->dup[k]) && (k0 < 0 || key[k] > key[k0])) k0 = k;
        }
        if (k0 < 0) { overlap_zero(r); return 0; }
        int q = mesh_clip(w, 0, B->n + 3 * k0, B->h[k0], A->nt + k0, eps);
        if (q == -2) return -2;
        if (q >= 0) {
            nf = q; buf = 1;
            if (nf > 0) mesh_sphere(w, buf, sc, &sr);
        }
        for (int k = 0; k < ntB && nf > 0; k++) {
            if (k == k0 || (B->dup && B->dup[k])) continue;
            if (dot3(B->n + 3 * k, sc) - B->h[k] + sr <= 0) continue;
            int j = m++;
            while (j > 0 && key[ord[j - 1]] < key[k]) { ord[j] = ord[j - 1]; j--; }
            ord[j] = k;
        }
    } else {
        int *nout = w->nout;
        if (face_separation(A, B, nout, sep_axis)) { overlap_zero(r); return 0; }
        for (int k = 0; k < ntB; k++) {
            if (nout[k] == 0) continue;
            int j = m++;
            while (j > 0 && nout[ord[j - 1]] < nout[k]) { ord[j] = ord[j - 1]; j--; }
            ord[j] = k;
        }
    }
    for (int i = 0; i < m && nf > 0; i++) {
        int k = ord[i];
        if (B->dup && B->dup[k]) continue;
        if (dot3(B->n + 3 * k, sc) - B->h[k] + sr <= 0) continue;
        int q = mesh_clip(w, buf, B->n + 3 * k, B->h[k], A->nt + k, eps);
        if (q == -2) return -2;
        if (q >= 0) {
            nf = q; buf = 1 - buf;
            if (nf > 0) mesh_sphere(w, buf, sc, &sr);
        }
    }
    if (nf == 0) { overlap_zero(r); return 0; }
    mesh_integrate(w, buf, A->nt, A->n, dAB, want_shadow, r);
    if (keep && r->volume > 0) keep_structure(w, buf, A, B, keep);
    return 0;
}

/* Overlap of A and B posed in the same frame. A's triangles are clipped by
 * B's planes (those that cut A, most cutting first). dAB is an optional
 * centre difference for the degenerate-normal fallback.
 *
 * hot: the pair touched at the last step. It skips the separation tests
 * (clipping finds an empty overlap anyway) and clips first by the planes of
 * B that face A most, which cut the most. With cull (the engine's fast
 * mode), that path does the same cuts in the same order with less work, so
 * its polygons are bit for bit those of the plain path:
 *   - A's triangles wholly beyond the first plane k0 are never copied: the
 *     first cut would drop them whole, and they give it no cap point;
 *   - after that cut, the planes that cannot reach the bounding sphere of
 *     what is left are dropped before the sort: every later point lies in
 *     that sphere (cuts only interpolate between points), so those planes
 *     would cut nothing; the others keep their relative order.
 * Planes that cut nothing change nothing, so the sequence of effective cuts,
 * and every polygon, is the plain path's. */
/* The round-off tolerance of a plane test in overlap_pair: the coordinates
 * are O(r_A + |x_B - x_A|). */
static inline double pair_eps(const posed_t *A, const double *dAB) {
    double ra = posed_extent(A);
    return 1e-13 * (ra + (dAB ? fabs(dAB[0]) + fabs(dAB[1]) + fabs(dAB[2]) : 0));
}

static void overlap_pair(const posed_t *A, const posed_t *B, const double *dAB, work_t *w, overlap_t *r,
                         double *sep_axis, int hot, int cull, int want_shadow, keep_t *keep) {
    int ntB = B->nt;
    if (sep_axis) sep_axis[0] = sep_axis[1] = sep_axis[2] = 0;
    int *ord = w->order, m = 0;
    int np = 0, buf = 0, overflow = 0;
    /* Each plane of B in turn; a plane that cannot reach the bounding sphere
     * of what is left cannot cut it. The sphere is refreshed after every
     * plane that cut (what is left only shrinks, so a stale sphere is still
     * a valid, looser bound). */
    double sc[3] = {0, 0, 0}, sr = INFINITY;
    double eps = pair_eps(A, dAB);
    r->fallback = 0; r->kept = 0;
    if (cull && hot && dAB && keep && keep->ok) {
        if (overlap_kept(A, B, dAB, w, r, keep, want_shadow, eps) == 0) { r->kept = 1; return; }
        r->kept = -1;
    }
    if (keep) keep->ok = 0;
    if (cull) {
        if (overlap_mesh(A, B, dAB, w, r, sep_axis, hot, want_shadow, eps, keep) == 0) { r->fallback = 0; return; }
        r->fallback = 1;
        if (sep_axis) sep_axis[0] = sep_axis[1] = sep_axis[2] = 0;
    }
    if (hot && dAB && cull) {
        double *key = w->key;
        int k0 = -1;
        for (int k = 0; k < ntB; k++) {
            key[k] = -dot3(B->n + 3 * k, dAB);      /* dAB = x_B - x_A: facing A is n.(x_A - x_B) > 0 */
            if (!(B->dup && B->dup[k]) && (k0 < 0 || key[k] > key[k0])) k0 = k;
        }
        if (k0 < 0) { overlap_zero(r); return; }
        const double *n0 = B->n + 3 * k0;
        double h0 = B->h[k0], *dv = w->vdist;
        for (int i = 0; i < A->nv; i++) dv[i] = dot3(A->v + 3 * i, n0) - h0;
        for (int f = 0; f < A->nt; f++) {
            const int *tr = A->t + 3 * f;
            if (dv[tr[0]] > eps && dv[tr[1]] > eps && dv[tr[2]] > eps) continue;   /* wholly beyond k0 */
            w->start[0][np] = 3 * np; w->count[0][np] = 3; w->tag[0][np] = f;
            for (int c = 0; c < 3; c++) memcpy(w->pts[0] + 3 * (3 * np + c), A->v + 3 * tr[c], 3 * sizeof(double));
            np++;
        }
        if (np == 0) { overlap_zero(r); return; }
        int q = clip_plane(w, 0, np, n0, h0, A->nt + k0, eps, &overflow);
        if (overflow) { overlap_zero(r); r->status = PC_WORKSPACE; return; }
        if (q >= 0) {
            np = q; buf = 1;
            if (np > 0) bounding_sphere(w, buf, np, sc, &sr);
        }
        for (int k = 0; k < ntB && np > 0; k++) {
            if (k == k0 || (B->dup && B->dup[k])) continue;
            if (dot3(B->n + 3 * k, sc) - B->h[k] + sr <= 0) continue;   /* cannot cut what is left */
            int j = m++;
            while (j > 0 && key[ord[j - 1]] < key[k]) { ord[j] = ord[j - 1]; j--; }
            ord[j] = k;
        }
        goto cut;
    }
    if (hot && dAB) {
        double *key = w->key;
        for (int k = 0; k < ntB; k++) {
            double f = -dot3(B->n + 3 * k, dAB);
            int j = m++;
            while (j > 0 && key[j - 1] < f) { ord[j] = ord[j - 1]; key[j] = key[j - 1]; j--; }
            ord[j] = k; key[j] = f;
        }
        goto fill;
    }
    /* distances of A's vertices to B's planes; separation by a face of B */
    int *nout = w->nout;
    if (face_separation(A, B, nout, sep_axis)) { overlap_zero(r); return; }
    /* the planes that cut A, most cutting first (insertion sort, small n) */
    for (int k = 0; k < ntB; k++) {
        if (nout[k] == 0) continue;
        int j = m++;
        while (j > 0 && nout[ord[j - 1]] < nout[k]) { ord[j] = ord[j - 1]; j--; }
        ord[j] = k;
    }
fill:
    /* A's triangles as the starting polygons */
    np = A->nt;
    for (int f = 0; f < np; f++) {
        w->start[0][f] = 3 * f; w->count[0][f] = 3; w->tag[0][f] = f;
        for (int c = 0; c < 3; c++) memcpy(w->pts[0] + 3 * (3 * f + c), A->v + 3 * A->t[3 * f + c], 3 * sizeof(double));
    }
cut:
    for (int i = 0; i < m && np > 0; i++) {
        int k = ord[i];
        if (B->dup && B->dup[k]) continue;                 /* the same plane as an earlier triangle */
        if (dot3(B->n + 3 * k, sc) - B->h[k] + sr <= 0) continue;
        int q = clip_plane(w, buf, np, B->n + 3 * k, B->h[k], A->nt + k, eps, &overflow);
        if (overflow) { overlap_zero(r); r->status = PC_WORKSPACE; return; }
        if (q >= 0) {
            np = q; buf = 1 - buf;
            if (np > 0) bounding_sphere(w, buf, np, sc, &sr);
        }
    }
    integrate(w, buf, np, A->nt, A->n, dAB, want_shadow, r);
}

/* Overlap of polyhedron A with the half-space beyond a plane n.x > h (the
 * wall's material side is n.x >= h ... here we keep n.x <= h): the part of A
 * with n.x <= h. The normal is -n (from the wall towards A) when wall_to_a. */
static void overlap_halfspace(const posed_t *A, const double *n, double h, work_t *w, int want_shadow, overlap_t *r) {
    int c = 0;
    for (int i = 0; i < A->nv; i++) c += dot3(A->v + 3 * i, n) - h > 0;
    if (c == A->nv) { overlap_zero(r); return; }
    int np = A->nt, buf = 0, overflow = 0;
    for (int f = 0; f < np; f++) {
        w->start[0][f] = 3 * f; w->count[0][f] = 3; w->tag[0][f] = f;
        for (int k = 0; k < 3; k++) memcpy(w->pts[0] + 3 * (3 * f + k), A->v + 3 * A->t[3 * f + k], 3 * sizeof(double));
    }
    if (c > 0) {
        double ra = 0;
        for (int i = 0; i < A->nv; i++) {
            double q = fabs(A->v[3 * i]) + fabs(A->v[3 * i + 1]) + fabs(A->v[3 * i + 2]);
            ra = q > ra ? q : ra;
        }
        int q = clip_plane(w, buf, np, n, h, -1, 1e-13 * (ra + fabs(h)), &overflow);
        if (q >= 0) { np = q; buf = 1; }
    }
    if (overflow) { overlap_zero(r); r->status = PC_WORKSPACE; return; }
    /* S for the wall side: the cap (tag -1) with the wall's outward normal n;
     * compute V, centroid via integrate (tag -1 is not an A face), then set
     * the normal: from the wall to A is -n. */
    double negn[3] = {-n[0], -n[1], -n[2]};
    integrate(w, buf, np, 0, NULL, negn, want_shadow, r);
    if (r->volume > 0) {
        r->normal[0] = -n[0]; r->normal[1] = -n[1]; r->normal[2] = -n[2];
        r->status = PC_OK;     /* the shadow on the plane normal to -n is the one computed */
    }
}

/* overlap_halfspace by one shared-vertex cut (the engine's fast path); the
 * polygon cut when the shared-vertex one gives up. */
static void overlap_halfspace_mesh(const posed_t *A, const double *n, double h, work_t *w, int want_shadow,
                                   overlap_t *r) {
    int c = 0;
    for (int i = 0; i < A->nv; i++) c += dot3(A->v + 3 * i, n) - h > 0;
    if (c == A->nv) { overlap_zero(r); return; }
    double ra = 0;
    for (int i = 0; i < A->nv; i++) {
        double q = fabs(A->v[3 * i]) + fabs(A->v[3 * i + 1]) + fabs(A->v[3 * i + 2]);
        ra = q > ra ? q : ra;
    }
    mesh_start(w, A);
    int buf = 0;
    if (c > 0) {
        int q = mesh_clip(w, 0, n, h, -1, 1e-13 * (ra + fabs(h)));
        if (q == -2) { overlap_halfspace(A, n, h, w, want_shadow, r); return; }
        if (q >= 0) buf = 1;
    }
    double negn[3] = {-n[0], -n[1], -n[2]};
    mesh_integrate(w, buf, 0, NULL, negn, want_shadow, r);
    if (r->volume > 0) {
        r->normal[0] = -n[0]; r->normal[1] = -n[1]; r->normal[2] = -n[2];
        r->status = PC_OK;
    }
}

/* ------------------------------------------------------------------ shape table */
typedef struct {
    int ns;
    const int *voff, *toff;     /* (ns+1) */
    const double *v;            /* local vertices */
    const int *t;               /* local triangles (indices local to the shape) */
    double *n, *h;              /* local unit normals and offsets per triangle */
    double *radius;             /* bounding radius about the local origin */
    double *box;                /* local bounding box per shape: lo[3], hi[3] */
    unsigned char *dup;         /* per triangle: its plane repeats an earlier triangle's of the shape */
    uint64_t *pmask;            /* per triangle: PC_MASK_WORDS words, the vertices of its plane's face */
    unsigned char *hasdup;      /* per shape: it has coplanar triangles (and at most 64 PC_MASK_WORDS vertices) */
    int *nface, *foff;          /* per shape: its polygonal faces (0: none, its triangles are its faces), their
                                 * first row in fs/fc/ftag (foff) and of their vertices in fi (at 3 * toff) */
    int *fs, *fc, *ftag, *fi;   /* per face: start in the shape's fi, vertex count, plane (first triangle); vertices */
    int *tplane;                /* per triangle of a shape with faces: the face of its plane (its first triangles), else -1 */
    int max_t, max_v;
} table_t;

/* The polygonal faces of shape s (with coplanar triangles): for each plane
 * (its first triangle f, not a dup), the boundary of the union of the plane's
 * triangles (those whose pmask is f's: the same test), traced along the
 * directed edges that appear once (an inner diagonal appears twice, once each
 * way), so the cycle turns as the triangles do (outward). Only the topology
 * is used: the vertices are the shape's, the plane f's, exactly. Any surprise
 * (a plane whose boundary is not one cycle, a face of more than 64 vertices,
 * a triangle in no face or in two) leaves nface[s] = 0: the triangles stay
 * the faces. Faces come in the order of their first triangles, so a loop over
 * them meets the planes in the order of a loop over the triangles that skips
 * the duplicates. */
static void merge_faces(table_t *T, int s) {
    int t0 = T->toff[s], nt = T->toff[s + 1] - t0, nv = T->voff[s + 1] - T->voff[s];
    int f0 = t0, q = 0, nfc = 0;                 /* rows from t0 (nfaces <= nt), vertices from 3 * t0 */
    int *fs = T->fs + f0, *fc = T->fc + f0, *ftag = T->ftag + f0, *fi = T->fi + 3 * (size_t)t0;
    T->nface[s] = 0; T->foff[s] = f0;
    int eu[3 * 64], ev[3 * 64], used[3 * 64], covered = 0;
    for (int f = 0; f < nt; f++) {
        if (T->dup[t0 + f]) continue;
        const uint64_t *mf = T->pmask + (size_t)PC_MASK_WORDS * (t0 + f);
        int ne = 0;
        for (int g = 0; g < nt; g++) {
            const uint64_t *mg = T->pmask + (size_t)PC_MASK_WORDS * (t0 + g);
            if (memcmp(mf, mg, sizeof(uint64_t) * PC_MASK_WORDS) != 0) continue;
            covered++;
            const int *tri = T->t + 3 * (t0 + g);
            for (int c = 0; c < 3; c++) {
                int a = tri[c], b = tri[(c + 1) % 3], k;
                for (k = 0; k < ne; k++) if (eu[k] == b && ev[k] == a) break;   /* the diagonal, the other way */
                if (k < ne) { eu[k] = eu[ne - 1]; ev[k] = ev[ne - 1]; ne--; continue; }
                if (ne == 3 * 64) return;
                eu[ne] = a; ev[ne] = b; ne++;
            }
        }
        if (ne < 3) return;
        memset(used, 0, sizeof(int) * ne);
        int m = 0, a = eu[0];
        fs[nfc] = q; ftag[nfc] = f;
        do {                                      /* follow a -> b */
            int k;
            for (k = 0; k < ne; k++) if (!used[k] && eu[k] == a) break;
            if (k == ne) return;
            used[k] = 1;
            fi[q + m++] = a;
            a = ev[k];
        } while (a != eu[0] && m <= ne);
        if (m != ne || a != eu[0]) return;          /* more than one cycle, or a vertex met twice */
        for (int i = 0; i < m; i++) if (fi[q + i] < 0 || fi[q + i] >= nv) return;
        fc[nfc] = m; q += m; nfc++;
    }
    if (covered != nt) return;                     /* a triangle in no face, or in two: keep the triangles */
    T->nface[s] = nfc;
}

static int table_init(table_t *T, int ns, const int *voff, const double *v, const int *toff, const int *t) {
    T->ns = ns; T->voff = voff; T->toff = toff; T->v = v; T->t = t;
    int ntot = toff[ns];
    T->n = malloc(sizeof(double) * 3 * (ntot + 1));
    T->h = malloc(sizeof(double) * (ntot + 1));
    T->radius = malloc(sizeof(double) * (ns + 1));
    T->box = malloc(sizeof(double) * 6 * (ns + 1));
    T->dup = calloc(ntot + 1, 1);
    int *rep = calloc(ntot + 1, sizeof(int));   /* per triangle: the earlier triangle it repeats, or itself */
    T->pmask = calloc((size_t)PC_MASK_WORDS * (ntot + 1), sizeof(uint64_t));
    T->hasdup = calloc(ns + 1, 1);
    T->nface = calloc(ns + 1, sizeof(int)); T->foff = calloc(ns + 1, sizeof(int));
    T->tplane = malloc(sizeof(int) * (ntot + 1));
    T->fs = calloc(ntot + 1, sizeof(int)); T->fc = calloc(ntot + 1, sizeof(int));
    T->ftag = calloc(ntot + 1, sizeof(int)); T->fi = calloc(3 * (size_t)ntot + 1, sizeof(int));
    if (!rep || !T->n || !T->h || !T->radius || !T->box || !T->dup || !T->pmask || !T->hasdup) { free(rep); return -1; }
    if (!T->nface || !T->foff || !T->fs || !T->fc || !T->ftag || !T->fi || !T->tplane) { free(rep); return -1; }
    for (int k = 0; k <= ntot; k++) T->tplane[k] = -1;
    T->max_t = 0; T->max_v = 0;
    for (int s = 0; s < ns; s++) {
        const double *V = v + 3 * voff[s];
        int nv = voff[s + 1] - voff[s], nt = toff[s + 1] - toff[s];
        if (nt > T->max_t) T->max_t = nt;
        if (nv > T->max_v) T->max_v = nv;
        double r = 0, *bx = T->box + 6 * s;
        for (int c = 0; c < 3; c++) { bx[c] = INFINITY; bx[3 + c] = -INFINITY; }
        for (int i = 0; i < nv; i++) {
            double q = sqrt(dot3(V + 3 * i, V + 3 * i));
            if (q > r) r = q;
            for (int c = 0; c < 3; c++) {
                if (V[3 * i + c] < bx[c]) bx[c] = V[3 * i + c];
                if (V[3 * i + c] > bx[3 + c]) bx[3 + c] = V[3 * i + c];
            }
        }
        T->radius[s] = r;
        for (int f = 0; f < nt; f++) {
            const int *tri = t + 3 * (toff[s] + f);
            const double *a = V + 3 * tri[0], *b = V + 3 * tri[1], *c = V + 3 * tri[2];
            double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
            double nn[3];
            cross3(e1, e2, nn);
            double l = sqrt(dot3(nn, nn));
            if (l > 0) { nn[0] /= l; nn[1] /= l; nn[2] /= l; }
            double *N = T->n + 3 * (toff[s] + f);
            N[0] = nn[0]; N[1] = nn[1]; N[2] = nn[2];
            /* offset from the mean of the three vertices (less round-off) */
            T->h[toff[s] + f] = (dot3(a, nn) + dot3(b, nn) + dot3(c, nn)) / 3.0;
            /* coplanar with an earlier triangle (a face split in triangles)? */
            rep[toff[s] + f] = f;
            for (int g = 0; g < f; g++) {
                const double *M = T->n + 3 * (toff[s] + g);
                if (dot3(M, nn) > 1 - 1e-12 && fabs(T->h[toff[s] + g] - T->h[toff[s] + f]) <= 1e-12 * r) {
                    T->dup[toff[s] + f] = 1;
                    rep[toff[s] + f] = g;
                    break;
                }
            }
        }
        /* a shape with coplanar triangles: each triangle's face, the vertices of every triangle of its plane
         * (the test above, against each earlier triangle, so that both members of a pair see each other) */
        int anydup = 0;
        for (int f = 0; f < nt; f++) anydup |= T->dup[toff[s] + f];
        if (!anydup) continue;
        if (nv <= 64 * PC_MASK_WORDS) {
            T->hasdup[s] = 1;
            for (int f = 0; f < nt; f++) {
                const double *Nf = T->n + 3 * (toff[s] + f);
                uint64_t *mf = T->pmask + (size_t)PC_MASK_WORDS * (toff[s] + f);
                for (int g = 0; g < nt; g++) {
                    const double *M = T->n + 3 * (toff[s] + g);
                    if (g != f && !(dot3(M, Nf) > 1 - 1e-12 && fabs(T->h[toff[s] + g] - T->h[toff[s] + f]) <= 1e-12 * r)) continue;
                    const int *tri = t + 3 * (toff[s] + g);
                    for (int c = 0; c < 3; c++) mf[tri[c] >> 6] |= (uint64_t)1 << (tri[c] & 63);
                }
            }
            merge_faces(T, s);
            for (int p = 0; p < T->nface[s]; p++) T->tplane[toff[s] + T->ftag[T->foff[s] + p]] = p;
        }
        /* once coplanarity is decided: each duplicate takes the plane (normal
         * and offset) of the earlier triangle it repeats, so that a plane is
         * one plane, to the bit, on every path */
        for (int f = 0; f < nt; f++) {
            int g = rep[toff[s] + f];
            if (g == f) continue;
            memcpy(T->n + 3 * (toff[s] + f), T->n + 3 * (toff[s] + g), 3 * sizeof(double));
            T->h[toff[s] + f] = T->h[toff[s] + g];
        }
    }
    free(rep);
    return 0;
}
static void table_free(table_t *T) {
    free(T->n); free(T->h); free(T->radius); free(T->box); free(T->dup); free(T->pmask); free(T->hasdup);
    free(T->nface); free(T->foff); free(T->fs); free(T->fc); free(T->ftag); free(T->fi); free(T->tplane);
}

/* the polygonal faces of shape s on P (nf = 0: none) */
static inline void posed_faces(const table_t *T, int s, posed_t *P) {
    P->nf = T->nface[s];
    int f0 = T->foff[s];
    P->fs = T->fs + f0; P->fc = T->fc + f0; P->ftag = T->ftag + f0; P->fi = T->fi + 3 * (size_t)T->toff[s];
}

/* pose shape s: rotated vertices (+ offset), rotated normals, offsets */
static void pose_shape(const table_t *T, int s, const double *R, const double *off,
                       double *vo, double *no, double *ho, posed_t *P) {
    int v0 = T->voff[s], nv = T->voff[s + 1] - v0, t0 = T->toff[s], nt = T->toff[s + 1] - t0;
    for (int i = 0; i < nv; i++) {
        double x[3];                  /* in registers, then stored once */
        matvec(R, T->v + 3 * (v0 + i), x);
        vo[3 * i] = x[0] + off[0]; vo[3 * i + 1] = x[1] + off[1]; vo[3 * i + 2] = x[2] + off[2];
    }
    for (int f = 0; f < nt; f++) {   /* a duplicate's plane is its earlier triangle's (table_init): the same numbers */
        double x[3];
        matvec(R, T->n + 3 * (t0 + f), x);
        no[3 * f] = x[0]; no[3 * f + 1] = x[1]; no[3 * f + 2] = x[2];
        ho[f] = T->h[t0 + f] + dot3(x, off);
    }
    P->nv = nv; P->nt = nt; P->v = vo; P->t = T->t + 3 * t0; P->n = no; P->h = ho;
    P->R = R; P->box = T->box + 6 * s; P->dup = T->dup + t0;
    P->pmask = T->hasdup[s] ? T->pmask + (size_t)PC_MASK_WORDS * t0 : NULL;
    P->off[0] = off[0]; P->off[1] = off[1]; P->off[2] = off[2];
    P->ra = 0;
    P->pn = P->ph = NULL; P->tplane = NULL;
    posed_faces(T, s, P);
}

/* ================================================================== batched geometry (public API) */
/* For P pairs: shape indices sa, sb into the table, positions (P,3), quaternions (P,4) w,x,y,z.
 * Outputs: volume (P), centroid (P,3), normal (P,3), footprint (P,2), area (P), status (P).
 * Returns 0, or -1 when memory could not be had. */
int pc_batch_overlap(int ns, const int *voff, const double *v, const int *toff, const int *t,
                     int npairs, const int *sa, const double *pa, const double *qa,
                     const int *sb, const double *pb, const double *qb,
                     double *vol, double *cen, double *nor, double *fp, double *area, int *status, int nthreads) {
    table_t T;
    if (table_init(&T, ns, voff, v, toff, t)) { table_free(&T); return -1; }
    int err = 0;
#ifdef _OPENMP
    if (nthreads < 1) nthreads = omp_get_max_threads();
#pragma omp parallel num_threads(nthreads)
#endif
    {
        work_t w;
        double *buf = malloc(sizeof(double) * (8 * (T.max_v + T.max_t) + 16));
        int ok = (work_init(&w, T.max_t, T.max_v) == 0) && buf;
        if (!ok) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            err = -1;
        }
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 8)
#endif
        for (int p = 0; p < npairs; p++) {
            if (!ok) continue;
            double RA[9], RB[9], zero[3] = {0, 0, 0}, d[3];
            quat_to_mat(qa + 4 * p, RA); quat_to_mat(qb + 4 * p, RB);
            d[0] = pb[3 * p] - pa[3 * p]; d[1] = pb[3 * p + 1] - pa[3 * p + 1]; d[2] = pb[3 * p + 2] - pa[3 * p + 2];
            double *va = buf, *na = va + 3 * T.max_v, *ha = na + 3 * T.max_t;
            double *vb = ha + T.max_t, *nb = vb + 3 * T.max_v, *hb = nb + 3 * T.max_t;
            posed_t A, B;
            pose_shape(&T, sa[p], RA, zero, va, na, ha, &A);
            pose_shape(&T, sb[p], RB, d, vb, nb, hb, &B);
            overlap_t r = {0};
            overlap_pair(&A, &B, d, &w, &r, NULL, 0, 0, 1, NULL);
            vol[p] = r.volume; area[p] = r.area; status[p] = r.status;
            for (int c = 0; c < 3; c++) {
                cen[3 * p + c] = r.volume > 0 ? r.centroid[c] + pa[3 * p + c] : NAN;
                nor[3 * p + c] = r.normal[c];
            }
            fp[2 * p] = r.footprint[0]; fp[2 * p + 1] = r.footprint[1];
        }
        if (ok) work_free(&w);
        free(buf);
    }
    table_free(&T);
    return err;
}

/* P polyhedra against planes: plane point (P,3), unit normal m (P,3) pointing
 * to the side where the polyhedron belongs; the overlap is the part of the
 * polyhedron with (x - point).m < 0. The normal returned is m (from the wall
 * towards the polyhedron). */
int pc_batch_wall(int ns, const int *voff, const double *v, const int *toff, const int *t,
                  int n, const int *s, const double *pos, const double *q, const double *wp, const double *wm,
                  double *vol, double *cen, double *nor, double *fp, double *area, int *status, int nthreads) {
    table_t T;
    if (table_init(&T, ns, voff, v, toff, t)) { table_free(&T); return -1; }
    int err = 0;
#ifdef _OPENMP
    if (nthreads < 1) nthreads = omp_get_max_threads();
#pragma omp parallel num_threads(nthreads)
#endif
    {
        work_t w;
        double *buf = malloc(sizeof(double) * (4 * (T.max_v + T.max_t) + 16));
        int ok = (work_init(&w, T.max_t, T.max_v) == 0) && buf;
        if (!ok) {
#ifdef _OPENMP
#pragma omp atomic write
#endif
            err = -1;
        }
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 8)
#endif
        for (int p = 0; p < n; p++) {
            if (!ok) continue;
            double R[9], zero[3] = {0, 0, 0};
            quat_to_mat(q + 4 * p, R);
            double *va = buf, *na = va + 3 * T.max_v, *ha = na + 3 * T.max_t;
            posed_t A;
            pose_shape(&T, s[p], R, zero, va, na, ha, &A);
            /* plane in the body-centred frame: keep m.x >= m.(wp - pos), i.e. clip by (-m).x <= -m.(wp-pos) */
            const double *m = wm + 3 * p;
            double rel[3] = {wp[3 * p] - pos[3 * p], wp[3 * p + 1] - pos[3 * p + 1], wp[3 * p + 2] - pos[3 * p + 2]};
            double nn[3] = {m[0], m[1], m[2]};
            double h = dot3(m, rel);
            /* the overlap is where m.x < h: clip with plane n = m, keep n.x <= h */
            overlap_t r = {0};
            overlap_halfspace(&A, nn, h, &w, 1, &r);
            /* overlap_halfspace returns normal -n = -m; from the wall to the body is +m */
            vol[p] = r.volume; area[p] = r.area; status[p] = r.status;
            for (int c = 0; c < 3; c++) {
                cen[3 * p + c] = r.volume > 0 ? r.centroid[c] + pos[3 * p + c] : NAN;
                nor[3 * p + c] = r.volume > 0 ? m[c] : NAN;
            }
            fp[2 * p] = r.footprint[0]; fp[2 * p + 1] = r.footprint[1];
        }
        if (ok) work_free(&w);
        free(buf);
    }
    table_free(&T);
    return err;
}

/* ================================================================== the engine */
/* Counters of one step (pc_engine_step's stat), named by pc_engine_stat_name. */
enum {
    PC_STAT_TOUCHING_PAIRS,      /* particle pairs in contact */
    PC_STAT_WALL_CONTACTS,       /* particle-wall contacts */
    PC_STAT_LISTED_PAIRS,        /* pairs in the neighbour list */
    PC_STAT_SLIDING,             /* contacts at the Coulomb limit */
    PC_STAT_SUM_CONTACT_FORCE,   /* sum over contacts of |F| (N) */
    PC_STAT_REBUILDS,            /* neighbour-list builds so far */
    PC_STAT_SUM_BODY_FORCE,      /* sum over bodies of |net contact force| (N) */
    PC_STAT_CLIPPED,             /* pairs whose overlap was computed (clipping) */
    PC_STAT_APART_SPHERES,       /* listed pairs apart by their bounding spheres */
    PC_STAT_APART_MOTION,        /* apart: cached axis, gap larger than the motion since it was measured */
    PC_STAT_APART_AXIS,          /* apart: cached axis re-measured with support functions */
    PC_STAT_APART_SEARCH,        /* apart: a separating axis found by the search */
    PC_STAT_OVERFLOWS,           /* pairs or wall contacts that overflowed the clipping workspace */
    PC_STAT_CLIP_FALLBACKS,      /* pairs the shared-vertex cuts gave up on (clipped as polygons) */
    PC_STAT_KEPT,                /* touching pairs computed from the structure kept from the last step */
    PC_STAT_KEPT_BROKEN,         /* ... whose structure no longer held (cut again) */
    PC_NSTAT
};
static const char *PC_STAT_NAMES[PC_NSTAT] = {
    "touching_pairs", "wall_contacts", "listed_pairs", "sliding_contacts", "sum_contact_force", "rebuilds",
    "sum_body_force", "clipped_pairs", "apart_by_spheres", "apart_by_motion_bound", "apart_by_cached_axis",
    "apart_by_axis_search", "workspace_overflows", "clip_fallbacks", "structure_kept", "structure_broken"};

#define PC_MAX_WALLS 16
#define PC_LARGE 4.0     /* a body PC_LARGE times the mean bounding radius stays out of the neighbour grid */
#define PC_KEEP_DOUBLES ((int)((sizeof(keep_t) + 5) / 6))   /* a kept structure, 6 bytes per double */
#define PC_PAIR_DOUBLES (24 + PC_KEEP_DOUBLES)   /* a pair's record in the engine state (see pc_engine_get_state) */
#define PC_WALL_DOUBLES 10       /* a wall contact's results: vol c(3) fp(2) area fn(3) */
#define PC_SCALARS (2 + PC_MAX_WALLS)   /* have_prev, builds, the wall positions of the last step */
#define PC_SEARCH_ITERATIONS 24  /* iterations of the separating-axis search before clipping decides */

typedef struct {
    int i, j;                 /* body rows, i < j */
    int touching;             /* in contact at the last step */
    int hot_used;             /* the clipping path of the last step (1: the pair had touched before) */
    double ft[3];             /* shear force on j by i (history) */
    double axis[3];           /* cached separating axis (unit, from i to j), 0 if none */
    double gap;               /* min over j - max over i of the vertices along axis when measured (m) */
    double mi0, mj0;          /* the motion bounds of i and j then (engine_t.motion) */
    /* per-step results (fp and area computed when the contacts are asked for) */
    double vol, c[3], n[3], fp[2], area, fn[3];
    keep_t keep;              /* the overlap's structure, for the next step */
} pair_t;

typedef struct {
    table_t T;
    int nb, nw, nthreads;
    const int *shape;          /* per body: row of the table (owned copy) */
    int *shape_own;
    int *group;                /* per body: group (a YADE clump), NULL for none: pairs of one group >= 0 never listed */
    int nsolid;                /* rows 0 .. nsolid - 1 are solids, the others facets (nb unless set: pc_engine_set_facets) */
    double *size;              /* per body d */
    double kv, ct, mu, mu_wall, skin;
    /* walls: axis (0,1,2), inward sign (+1 lo wall, -1 hi wall) */
    int wall_axis[PC_MAX_WALLS];
    double wall_sign[PC_MAX_WALLS];
    double wall_pos[PC_MAX_WALLS];   /* of the last step */
    /* per body pose state */
    double *R, *Rprev, *x, *xprev, *xbuild, *rv, *rn, *rh;
    double *ra;                /* per body: posed_extent of its posed vertices rv */
    double *rpn, *rph;         /* per body with faces: its planes by face, posed (the same numbers as rn, rh) */
    int *poffb;                /* offsets into rpn (x 3) and rph per body */
    double *motion;            /* per body: sum over steps of a bound on any vertex's displacement (m) */
    double *spin;              /* per body: rotation vector of the last step (small angles) */
    int fast;                  /* 1: proofs of separation, culled clipping, shadows on demand; 0: the plain path */
    int parallel_min;          /* pairs + body-wall tests below which a step runs on one thread */
    int shadows_ready;         /* the touching contacts' shadows belong to the last step */
    int *voffb, *toffb;        /* offsets into rv (vertices) and rn (triangles) per body */
    int have_prev;
    /* neighbour list */
    pair_t *pairs; int npairs, cap_pairs;
    pair_t *spare; int cap_spare;
    /* wall contacts: nb x nw */
    double *wft;               /* shear history per body-wall (nb*nw*3) */
    double *wres;              /* per body-wall: vol, c(3), fp(2), area, fn(3) : 10 doubles */
    int *wtouch;
    /* workspaces */
    work_t *work;
    double *cellbuf; int *cellhead, *cellnext; int cellcap;
    long nbuild;
    double stat[PC_NSTAT];
} engine_t;

void pc_engine_free(engine_t *E);

/* PC_PARALLEL_MIN, or POLYCONTACT_PARALLEL_MIN when it is a number >= 0 */
static int parallel_min_from_env(void) {
    const char *s = getenv("POLYCONTACT_PARALLEL_MIN");
    if (!s || !*s) return PC_PARALLEL_MIN;
    char *end;
    long v = strtol(s, &end, 10);
    return (*end == 0 && v >= 0 && v < 1000000000L) ? (int)v : PC_PARALLEL_MIN;
}

engine_t *pc_engine_new(int ns, const int *voff, const double *v, const int *toff, const int *t,
                        int nb, const int *shape, const double *size, int nw, const int *wall_axis,
                        const double *wall_sign, double kv, double ct, double mu, double mu_wall,
                        double skin, int nthreads) {
    engine_t *E = calloc(1, sizeof(engine_t));
    if (!E) return NULL;
    /* own copies of the shape table (the caller's arrays may go away) */
    int nvt = voff[ns], ntt = toff[ns];
    int *vo = malloc(sizeof(int) * (ns + 1)), *to = malloc(sizeof(int) * (ns + 1));
    double *vv = malloc(sizeof(double) * 3 * (nvt + 1));
    int *tt = malloc(sizeof(int) * 3 * (ntt + 1));
    if (!vo || !to || !vv || !tt) { free(vo); free(to); free(vv); free(tt); free(E); return NULL; }
    memcpy(vo, voff, sizeof(int) * (ns + 1)); memcpy(to, toff, sizeof(int) * (ns + 1));
    memcpy(vv, v, sizeof(double) * 3 * nvt); memcpy(tt, t, sizeof(int) * 3 * ntt);
    if (table_init(&E->T, ns, vo, vv, to, tt)) { pc_engine_free(E); return NULL; }
    if (nw < 0 || nw > PC_MAX_WALLS) { pc_engine_free(E); return NULL; }
    E->nb = nb; E->nw = nw; E->nsolid = nb;
    E->fast = 1;
    E->shape_own = malloc(sizeof(int) * (nb + 1)); E->size = malloc(sizeof(double) * (nb + 1));
    memcpy(E->shape_own, shape, sizeof(int) * nb); memcpy(E->size, size, sizeof(double) * nb);
    E->shape = E->shape_own;
    for (int k = 0; k < E->nw; k++) { E->wall_axis[k] = wall_axis[k]; E->wall_sign[k] = wall_sign[k]; }
    E->kv = kv; E->ct = ct; E->mu = mu; E->mu_wall = mu_wall; E->skin = skin;
#ifdef _OPENMP
    if (nthreads < 1) nthreads = omp_get_max_threads();
#else
    nthreads = 1;
#endif
    E->nthreads = nthreads;
    E->parallel_min = parallel_min_from_env();
    E->R = malloc(sizeof(double) * 9 * nb); E->Rprev = malloc(sizeof(double) * 9 * nb);
    E->x = malloc(sizeof(double) * 3 * nb); E->xprev = malloc(sizeof(double) * 3 * nb);
    E->xbuild = malloc(sizeof(double) * 3 * nb);
    E->motion = calloc(nb + 1, sizeof(double)); E->spin = calloc(3 * (size_t)nb + 1, sizeof(double));
    E->voffb = malloc(sizeof(int) * (nb + 1)); E->toffb = malloc(sizeof(int) * (nb + 1));
    E->voffb[0] = 0; E->toffb[0] = 0;
    for (int b = 0; b < nb; b++) {
        int s = shape[b];
        E->voffb[b + 1] = E->voffb[b] + (voff[s + 1] - voff[s]);
        E->toffb[b + 1] = E->toffb[b] + (toff[s + 1] - toff[s]);
    }
    E->rv = malloc(sizeof(double) * 3 * (E->voffb[nb] + 1));
    E->rn = malloc(sizeof(double) * 3 * (E->toffb[nb] + 1));
    E->rh = malloc(sizeof(double) * (E->toffb[nb] + 1));
    E->ra = calloc(nb + 1, sizeof(double));
    E->poffb = malloc(sizeof(int) * (nb + 1));
    if (E->poffb) {
        E->poffb[0] = 0;
        for (int b = 0; b < nb; b++) E->poffb[b + 1] = E->poffb[b] + E->T.nface[shape[b]];
        E->rpn = malloc(sizeof(double) * 3 * (E->poffb[nb] + 1)); E->rph = malloc(sizeof(double) * (E->poffb[nb] + 1));
    }
    E->wft = calloc((size_t)nb * E->nw * 3 + 1, sizeof(double));
    E->wres = calloc((size_t)nb * E->nw * 10 + 1, sizeof(double));
    E->wtouch = calloc((size_t)nb * E->nw + 1, sizeof(int));
    E->work = calloc(nthreads, sizeof(work_t));
    if (!E->R || !E->Rprev || !E->x || !E->xprev || !E->xbuild || !E->motion || !E->spin || !E->rv || !E->rn || !E->rh || !E->ra || !E->poffb || !E->rpn || !E->rph || !E->wft ||
        !E->wres || !E->wtouch || !E->work) { pc_engine_free(E); return NULL; }
    for (int k = 0; k < nthreads; k++)
        if (work_init(&E->work[k], E->T.max_t, E->T.max_v)) { pc_engine_free(E); return NULL; }
    E->have_prev = 0;
    E->npairs = 0;
    return E;
}

void pc_engine_free(engine_t *E) {
    if (!E) return;
    if (E->work) for (int k = 0; k < E->nthreads; k++) work_free(&E->work[k]);
    free(E->work);
    free((void *)E->T.voff); free((void *)E->T.toff); free((void *)E->T.v); free((void *)E->T.t);
    table_free(&E->T);
    free(E->shape_own); free(E->size); free(E->group);
    free(E->R); free(E->Rprev); free(E->x); free(E->xprev); free(E->xbuild); free(E->voffb); free(E->toffb);
    free(E->motion); free(E->spin);
    free(E->rv); free(E->rn); free(E->rh); free(E->ra); free(E->poffb); free(E->rpn); free(E->rph); free(E->pairs); free(E->spare); free(E->wft); free(E->wres);
    free(E->wtouch); free(E->cellbuf); free(E->cellhead); free(E->cellnext);
    free(E);
}

static double body_radius(const engine_t *E, int b) { return E->T.radius[E->shape[b]]; }

/* List the pair (i, j), i < j, at the end of the new list (E->spare, *np
 * pairs so far) when their bounding spheres (ri: body i's radius) come
 * within the skin of each other and they are not of one group
 * (pc_engine_set_groups); returns 0, or -1 when memory could not be had. */
static inline int never_pair(const engine_t *E, int i, int j) {
    return (E->group && E->group[i] >= 0 && E->group[i] == E->group[j])   /* members of one clump */
           || (i >= E->nsolid && j >= E->nsolid);                         /* two facets */
}

/* Drop the listed pairs that are never a pair (after pc_engine_set_groups or _set_facets). */
static void drop_never_pairs(engine_t *E) {
    int q = 0;
    for (int k = 0; k < E->npairs; k++) {
        const pair_t *p = E->pairs + k;
        if (never_pair(E, p->i, p->j)) continue;
        if (q != k) E->pairs[q] = *p;
        q++;
    }
    E->npairs = q;
}

static int list_pair(engine_t *E, int i, int j, double ri, int *np) {
    if (never_pair(E, i, j)) return 0;
    double d[3] = {E->x[3 * j] - E->x[3 * i], E->x[3 * j + 1] - E->x[3 * i + 1], E->x[3 * j + 2] - E->x[3 * i + 2]};
    double reach = ri + body_radius(E, j) + E->skin;
    if (dot3(d, d) > reach * reach) return 0;
    if (*np >= E->cap_spare) {
        int nc2 = E->cap_spare ? 2 * E->cap_spare : 1024;
        pair_t *s = realloc(E->spare, sizeof(pair_t) * nc2);
        if (!s) return -1;
        E->spare = s; E->cap_spare = nc2;
    }
    pair_t *p = E->spare + (*np)++;
    memset(p, 0, sizeof(*p));
    p->i = i; p->j = j;
    return 0;
}

/* cell-grid neighbour search on bounding spheres with margin skin; keeps the
 * history of pairs present in the old list (both lists sorted by (i, j)) */
static int rebuild(engine_t *E) {
    int nb = E->nb;
    /* Bodies much larger than the mean (a user scene's facets and slabs:
     * PC_LARGE times the mean bounding radius) stay out of the grid, whose
     * cells they would make as wide as themselves, and are listed against
     * every body by their bounding spheres. The list is the same either way
     * (every pair within reach, sorted by (i, j)); a scene without them
     * builds its grid exactly as before. */
    double rmean = 0;
    for (int b = 0; b < nb; b++) rmean += body_radius(E, b);
    rmean /= nb > 0 ? nb : 1;
    char *large = calloc(nb + 1, 1);
    if (!large) return -1;
    int nlarge = 0;
    for (int b = 0; b < nb; b++) if (body_radius(E, b) > PC_LARGE * rmean) { large[b] = 1; nlarge++; }
    int *biglist = malloc(sizeof(int) * (nlarge + 1));       /* the large bodies, in increasing order */
    if (!biglist) { free(large); free(biglist); return -1; }
    for (int b = 0, q = 0; b < nb; b++) if (large[b]) biglist[q++] = b;
    double rmax = 0, lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (int b = 0; b < nb; b++) {
        if (large[b]) continue;
        double r = body_radius(E, b);
        if (r > rmax) rmax = r;
        for (int c = 0; c < 3; c++) { double q = E->x[3 * b + c]; if (q < lo[c]) lo[c] = q; if (q > hi[c]) hi[c] = q; }
    }
    double cell = 2 * rmax + E->skin;
    int nc[3];
    long ncell = 1;
    for (int c = 0; c < 3; c++) {
        double span = hi[c] - lo[c];
        if (!isfinite(span)) { free(large); free(biglist); return -2; }
        nc[c] = (int)(span / cell);          /* cells at least `cell` wide */
        if (nc[c] > 256) nc[c] = 256;
        if (nc[c] < 1) nc[c] = 1;
        ncell *= nc[c];
    }
    if (ncell > E->cellcap) {
        free(E->cellhead);
        E->cellhead = malloc(sizeof(int) * ncell);
        E->cellcap = (int)ncell;
        if (!E->cellhead) { free(large); free(biglist); return -1; }
    }
    free(E->cellnext);
    E->cellnext = malloc(sizeof(int) * (nb + 1));
    if (!E->cellnext) { free(large); free(biglist); return -1; }
    for (long k = 0; k < ncell; k++) E->cellhead[k] = -1;
    double csz[3];
    for (int c = 0; c < 3; c++) csz[c] = (hi[c] - lo[c]) / nc[c] * (1 + 1e-12) + 1e-300;   /* >= cell */
    int *cidx = malloc(sizeof(int) * 3 * (nb + 1));
    if (!cidx) { free(large); free(biglist); return -1; }
    for (int b = nb - 1; b >= 0; b--) {
        if (large[b]) continue;
        int ci[3];
        for (int c = 0; c < 3; c++) {
            ci[c] = (int)((E->x[3 * b + c] - lo[c]) / csz[c]);
            if (ci[c] >= nc[c]) ci[c] = nc[c] - 1;
            if (ci[c] < 0) ci[c] = 0;
            cidx[3 * b + c] = ci[c];
        }
        long k = ((long)ci[0] * nc[1] + ci[1]) * nc[2] + ci[2];
        E->cellnext[b] = E->cellhead[k];
        E->cellhead[k] = b;
    }
    /* new list into spare; pairs ordered by i then j (we emit per i, then sort j) */
    int np = 0;
    for (int i = 0; i < nb; i++) {
        int start = np;
        double ri = body_radius(E, i);
        /* a large body, or a small one against the large ones: by bounding spheres, j in increasing order */
        for (int q = 0; q < (large[i] ? nb - i - 1 : nlarge); q++) {
            int j = large[i] ? i + 1 + q : biglist[q];
            if (j <= i) continue;
            if (list_pair(E, i, j, ri, &np)) { free(cidx); free(large); free(biglist); return -1; }
        }
        if (large[i]) continue;             /* its partners are listed, in order */
        for (int dx = -1; dx <= 1; dx++) for (int dy = -1; dy <= 1; dy++) for (int dz = -1; dz <= 1; dz++) {
            int a = cidx[3 * i] + dx, b2 = cidx[3 * i + 1] + dy, c2 = cidx[3 * i + 2] + dz;
            if (a < 0 || b2 < 0 || c2 < 0 || a >= nc[0] || b2 >= nc[1] || c2 >= nc[2]) continue;
            for (int j = E->cellhead[((long)a * nc[1] + b2) * nc[2] + c2]; j >= 0; j = E->cellnext[j]) {
                if (j <= i) continue;
                if (list_pair(E, i, j, ri, &np)) { free(cidx); free(large); free(biglist); return -1; }
            }
        }
        /* sort this i's partners by j (insertion sort: few) */
        for (int a = start + 1; a < np; a++) {
            pair_t tmp = E->spare[a];
            int b3 = a;
            while (b3 > start && E->spare[b3 - 1].j > tmp.j) { E->spare[b3] = E->spare[b3 - 1]; b3--; }
            E->spare[b3] = tmp;
        }
    }
    free(cidx);
    free(large);
    free(biglist);
    /* carry the history over (merge of two sorted lists) */
    int a = 0;
    for (int k = 0; k < np; k++) {
        pair_t *p = E->spare + k;
        while (a < E->npairs && (E->pairs[a].i < p->i || (E->pairs[a].i == p->i && E->pairs[a].j < p->j))) a++;
        if (a < E->npairs && E->pairs[a].i == p->i && E->pairs[a].j == p->j) {
            *p = E->pairs[a];                        /* history, proofs, kept structure, last results */
        }
    }
    pair_t *tmp = E->pairs; int tcap = E->cap_pairs;
    E->pairs = E->spare; E->cap_pairs = E->cap_spare; E->npairs = np;
    E->spare = tmp; E->cap_spare = tcap;
    memcpy(E->xbuild, E->x, sizeof(double) * 3 * nb);
    E->nbuild++;
    return 0;
}

/* displacement over the last step of the material point of body b now at c */
static void point_disp(const engine_t *E, int b, const double *c, double *du) {
    if (!E->have_prev) { du[0] = du[1] = du[2] = 0; return; }
    const double *x = E->x + 3 * b, *xp = E->xprev + 3 * b, *R = E->R + 9 * b, *Rp = E->Rprev + 9 * b;
    double r[3] = {c[0] - x[0], c[1] - x[1], c[2] - x[2]}, loc[3], old[3];
    mattvec(R, r, loc);           /* in the body frame */
    matvec(Rp, loc, old);         /* where it was */
    du[0] = c[0] - (xp[0] + old[0]); du[1] = c[1] - (xp[1] + old[1]); du[2] = c[2] - (xp[2] + old[2]);
}

/* rotation vector of body b over the step (small angles): the axial vector
 * of W = R Rp^T, zero before the first step */
static void body_spin(const engine_t *E, int b, double *w) {
    if (!E->have_prev) { w[0] = w[1] = w[2] = 0; return; }
    const double *R = E->R + 9 * b, *Rp = E->Rprev + 9 * b;
    double W[9];
    for (int r = 0; r < 3; r++) for (int c = 0; c < 3; c++)
        W[3 * r + c] = R[3 * r] * Rp[3 * c] + R[3 * r + 1] * Rp[3 * c + 1] + R[3 * r + 2] * Rp[3 * c + 2];
    w[0] = 0.5 * (W[7] - W[5]); w[1] = 0.5 * (W[2] - W[6]); w[2] = 0.5 * (W[3] - W[1]);
}

/* spin of body b about n over the step (rotation angle, small) */
static inline double spin_about(const engine_t *E, int b, const double *n) { return dot3(E->spin + 3 * b, n); }

/* A bound on the displacement of any vertex of body b over the last step:
 * |x - x_prev| + r_b |R - R_prev|_F / sqrt(2). For rotations R, R_prev the
 * largest stretch of R - R_prev is 2 sin(theta/2) = |R - R_prev|_F / sqrt(2),
 * theta the angle between them; 1e-9 covers the round-off of the poses. */
static double body_motion(const engine_t *E, int b) {
    if (!E->have_prev) return 0;
    const double *x = E->x + 3 * b, *xp = E->xprev + 3 * b, *R = E->R + 9 * b, *Rp = E->Rprev + 9 * b;
    double dx[3] = {x[0] - xp[0], x[1] - xp[1], x[2] - xp[2]}, f = 0;
    for (int k = 0; k < 9; k++) f += (R[k] - Rp[k]) * (R[k] - Rp[k]);
    return (sqrt(dot3(dx, dx)) + E->T.radius[E->shape[b]] * sqrt(0.5 * f)) * (1 + 1e-9);
}

/* tangential update; ft in/out, returns 1 when sliding */
static int tangential(double *ft, const double *n, double twist, const double *du, double kt, double mu, double fn) {
    double f0 = sqrt(dot3(ft, ft));
    double fdn = dot3(ft, n);
    double f[3] = {ft[0] - fdn * n[0], ft[1] - fdn * n[1], ft[2] - fdn * n[2]};
    double f1 = sqrt(dot3(f, f));
    if (f1 > 0) { f[0] *= f0 / f1; f[1] *= f0 / f1; f[2] *= f0 / f1; }
    if (twist != 0) {
        double nf[3];
        cross3(n, f, nf);
        f[0] += twist * nf[0]; f[1] += twist * nf[1]; f[2] += twist * nf[2];
    }
    double dn = dot3(du, n);
    f[0] -= kt * (du[0] - dn * n[0]); f[1] -= kt * (du[1] - dn * n[1]); f[2] -= kt * (du[2] - dn * n[2]);
    double m = sqrt(dot3(f, f)), cap = mu * fn;
    int slide = 0;
    if (m > cap) { double s = m > 0 ? cap / m : 0; f[0] *= s; f[1] *= s; f[2] *= s; slide = 1; }
    ft[0] = f[0]; ft[1] = f[1]; ft[2] = f[2];
    return slide;
}

/* ------------------------------------------------------------------ proofs of separation */
/* Largest u.v over the n vertices v. */
static inline double support_max(const double *v, int n, const double *u, int *arg) {
    double m = -INFINITY;
    int k = 0;
    for (int a = 0; a < n; a++) { double s = dot3(v + 3 * a, u); if (s > m) { m = s; k = a; } }
    if (arg) *arg = k;
    return m;
}

/* Smallest u.v over the n vertices v. */
static inline double support_min(const double *v, int n, const double *u, int *arg) {
    double m = INFINITY;
    int k = 0;
    for (int a = 0; a < n; a++) { double s = dot3(v + 3 * a, u); if (s < m) { m = s; k = a; } }
    if (arg) *arg = k;
    return m;
}

/* The gap along the unit axis u (from A to B) of A's vertices va and B's
 * vertices vb + d: min over B - max over A. Positive: the plane normal to u
 * between them separates the two hulls. */
static inline double axis_gap(const double *va, int na, const double *vb, int nb, const double *d, const double *u) {
    return support_min(vb, nb, u, NULL) + dot3(d, u) - support_max(va, na, u, NULL);
}

/* Search for a separating axis of the hulls of A's vertices va and B's
 * vertices vb + d, from a guess (any non-zero vector, from A to B). It is
 * Gilbert's iteration on the Minkowski difference C = A - B: v is a point of
 * C, the support point w of C along -v is found, and v moves to the point of
 * the segment [v, w] closest to the origin. Each direction is tried as an
 * axis on the way: the answer is a proof (the gap is measured over every
 * vertex), never a guess. Returns 1 with the unit axis and its gap > margin,
 * or 0 (touching, or too close to prove within maxit iterations: the
 * clipping decides). */
static int find_axis(const double *va, int na, const double *vb, int nb, const double *d, const double *guess,
                     double margin, int maxit, double *axis, double *gap) {
    double u[3] = {guess[0], guess[1], guess[2]}, v[3] = {0, 0, 0};
    for (int it = 0; it < maxit; it++) {
        double l = sqrt(dot3(u, u));
        if (!(l > 0)) return 0;
        u[0] /= l; u[1] /= l; u[2] /= l;
        int ia, ib;
        double ma = support_max(va, na, u, &ia), mb = support_min(vb, nb, u, &ib) + dot3(d, u);
        if (mb - ma > margin) {
            axis[0] = u[0]; axis[1] = u[1]; axis[2] = u[2];
            *gap = mb - ma;
            return 1;
        }
        /* w: the point of C farthest along u (a_ia - b_ib), the support along -v */
        const double *pa = va + 3 * ia, *pb = vb + 3 * ib;
        double w[3] = {pa[0] - pb[0] - d[0], pa[1] - pb[1] - d[1], pa[2] - pb[2] - d[2]};
        if (it == 0) {
            v[0] = w[0]; v[1] = w[1]; v[2] = w[2];
        } else {
            double e[3] = {w[0] - v[0], w[1] - v[1], w[2] - v[2]}, ee = dot3(e, e);
            if (!(ee > 0)) return 0;
            double t = -dot3(v, e) / ee;
            if (!(t > 0)) return 0;                    /* no progress: v is (nearly) the closest point */
            if (t > 1) t = 1;
            v[0] += t * e[0]; v[1] += t * e[1]; v[2] += t * e[2];
        }
        if (dot3(v, v) <= margin * margin) return 0;   /* C reaches the origin: touching */
        u[0] = -v[0]; u[1] = -v[1]; u[2] = -v[2];
    }
    return 0;
}

/* Body b of the engine as a posed_t, field by field: vertices v, offsets
 * h (its normals are the posed E->rn), placed at off (NULL: the origin). */
static inline void posed_body(const engine_t *E, int b, const double *v, const double *h, const double *off, posed_t *P) {
    int s = E->shape[b];
    P->nv = E->voffb[b + 1] - E->voffb[b]; P->nt = E->toffb[b + 1] - E->toffb[b];
    P->v = v; P->t = E->T.t + 3 * E->T.toff[s]; P->n = E->rn + 3 * E->toffb[b]; P->h = h;
    P->R = E->R + 9 * b; P->box = E->T.box + 6 * s; P->dup = E->T.dup + E->T.toff[s];
    P->off[0] = off ? off[0] : 0; P->off[1] = off ? off[1] : 0; P->off[2] = off ? off[2] : 0;
    P->pmask = E->T.hasdup[s] ? E->T.pmask + (size_t)PC_MASK_WORDS * E->T.toff[s] : NULL;
    P->ra = 0;
    P->pn = P->ph = NULL; P->tplane = NULL;
    posed_faces(&E->T, s, P);
}

/* ------------------------------------------------------------------ one pair, one step */
/* B (body j) posed relative to A (body i): vertices + d and plane offsets
 * + n.d, in the thread's scratch w->dA (sized max_v * (max_t + 1)). */
static void pose_pair(const engine_t *E, int i, int j, const double *d, work_t *w, posed_t *A, posed_t *B,
                      const keep_t *K) {
    const double *vi = E->rv + 3 * E->voffb[i], *vj = E->rv + 3 * E->voffb[j];
    int nvj = E->voffb[j + 1] - E->voffb[j], ntj = E->toffb[j + 1] - E->toffb[j];
    double *vjr = w->dA, *hj = w->dA + 3 * E->T.max_v;
    int s = E->shape[j], nf = E->T.nface[s];
    const unsigned char *dup = E->T.dup + E->T.toff[s];
    const double *nj = E->rn + 3 * E->toffb[j];
    if (K) {
        /* for overlap_kept only: the vertices of B its structure names, and
         * the planes of B that are no duplicate (what it reads) */
        for (int v = 0; v < K->nv; v++) {
            if (K->vt[v] != KV_B && K->vt[v] != KV_BEDGE) continue;
            for (int e = 0; e < (K->vt[v] == KV_B ? 1 : 2); e++) {
                int a = e ? K->vb[v] : K->va[v];
                vjr[3 * a] = vj[3 * a] + d[0]; vjr[3 * a + 1] = vj[3 * a + 1] + d[1]; vjr[3 * a + 2] = vj[3 * a + 2] + d[2];
            }
        }
        if (!nf)
            for (int f = 0; f < ntj; f++) if (!dup[f]) hj[f] = E->rh[E->toffb[j] + f] + dot3(nj + 3 * f, d);
    } else {
        for (int a = 0; a < nvj; a++) {
            vjr[3 * a] = vj[3 * a] + d[0]; vjr[3 * a + 1] = vj[3 * a + 1] + d[1]; vjr[3 * a + 2] = vj[3 * a + 2] + d[2];
        }
        for (int f = 0; f < ntj; f++) hj[f] = E->rh[E->toffb[j] + f] + dot3(nj + 3 * f, d);
    }
    posed_body(E, i, vi, E->rh + E->toffb[i], NULL, A);
    posed_body(E, j, vjr, hj, d, B);
    A->ra = E->ra[i];
    if (K && nf) {
        /* B's planes by face, contiguous (what overlap_kept reads of them), their offsets moved by d
         * as the triangles' would be: the same numbers; B's planes by triangle are not posed */
        const double *pn = E->rpn + 3 * E->poffb[j], *ph = E->rph + E->poffb[j];
        for (int p = 0; p < nf; p++) hj[p] = ph[p] + dot3(pn + 3 * p, d);
        B->pn = pn; B->ph = hj; B->tplane = E->T.tplane + E->T.toff[s];
        B->h = NULL;
    }
}

/* Keep a proof of separation for the next steps: the axis, its gap and the
 * two bodies' motion bounds now. */
static inline void keep_axis(const engine_t *E, pair_t *p, const double *u, double gap) {
    p->axis[0] = u[0]; p->axis[1] = u[1]; p->axis[2] = u[2];
    p->gap = gap; p->mi0 = E->motion[p->i]; p->mj0 = E->motion[p->j];
}

static inline void drop_axis(pair_t *p) { p->axis[0] = p->axis[1] = p->axis[2] = 0; p->gap = 0; }

/* One listed pair: proofs of separation, else the overlap and the contact
 * law. cnt: the thread's counters (PC_STAT_*). */
static void pair_step(engine_t *E, pair_t *p, work_t *w, int *cnt) {
    int i = p->i, j = p->j;
    int hot = p->touching;
    p->touching = 0;
    double d[3] = {E->x[3 * j] - E->x[3 * i], E->x[3 * j + 1] - E->x[3 * i + 1], E->x[3 * j + 2] - E->x[3 * i + 2]};
    double reach = body_radius(E, i) + body_radius(E, j);
    if (dot3(d, d) >= reach * reach) { memset(p->ft, 0, sizeof(p->ft)); cnt[PC_STAT_APART_SPHERES]++; return; }
    const double *vi = E->rv + 3 * E->voffb[i], *vj = E->rv + 3 * E->voffb[j];
    int nvi = E->voffb[i + 1] - E->voffb[i], nvj = E->voffb[j + 1] - E->voffb[j];
    /* a gap is trusted above the round-off of the posed vertices and of d */
    double margin = 1e-12 * (reach + fabs(d[0]) + fabs(d[1]) + fabs(d[2]));
    int has_axis = p->axis[0] != 0 || p->axis[1] != 0 || p->axis[2] != 0;
    if (has_axis && E->fast) {
        /* No vertex of i moved by more than motion[i] - mi0 since the gap was
         * measured (likewise j): a gap larger than both still separates. */
        double moved = (E->motion[i] - p->mi0) + (E->motion[j] - p->mj0);
        if (moved + margin < p->gap) { memset(p->ft, 0, sizeof(p->ft)); cnt[PC_STAT_APART_MOTION]++; return; }
        double g = axis_gap(vi, nvi, vj, nvj, d, p->axis);
        if (g > margin) { keep_axis(E, p, p->axis, g); memset(p->ft, 0, sizeof(p->ft)); cnt[PC_STAT_APART_AXIS]++; return; }
    } else if (has_axis) {
        /* the plain path: max over i of u.v < min over j of u.(v + d) */
        double mi = -INFINITY, mj = INFINITY;
        for (int a = 0; a < nvi; a++) { double s = dot3(vi + 3 * a, p->axis); if (s > mi) mi = s; }
        double od = dot3(d, p->axis);
        for (int a = 0; a < nvj && mj > mi; a++) { double s = dot3(vj + 3 * a, p->axis) + od; if (s < mj) mj = s; }
        if (mi < mj) { memset(p->ft, 0, sizeof(p->ft)); cnt[PC_STAT_APART_AXIS]++; return; }
    }
    int searched_d = 0;       /* the search below ran from d (and failed) */
    if (E->fast && !hot) {
        double u[3], g;
        searched_d = !has_axis;
        if (find_axis(vi, nvi, vj, nvj, d, has_axis ? p->axis : d, margin, PC_SEARCH_ITERATIONS, u, &g)) {
            keep_axis(E, p, u, g); memset(p->ft, 0, sizeof(p->ft)); cnt[PC_STAT_APART_SEARCH]++; return;
        }
    }
    posed_t A, B;
    overlap_t r = {0};
    double sep[3] = {0, 0, 0};
    cnt[PC_STAT_CLIPPED]++;
    int kept = 0;
    if (E->fast && hot && p->keep.ok) {
        /* the structure kept from the last step, on B posed only as far as it reads; else the cuts */
        pose_pair(E, i, j, d, w, &A, &B, &p->keep);
        kept = overlap_kept(&A, &B, d, w, &r, &p->keep, 0, pair_eps(&A, d)) == 0 ? 1 : -1;
    }
    if (kept == 1) {
        r.kept = 1;
    } else {
        pose_pair(E, i, j, d, w, &A, &B, NULL);
        if (kept == -1) p->keep.ok = 0;
        overlap_pair(&A, &B, d, w, &r, sep, hot, E->fast, !E->fast, &p->keep);
        if (kept == -1) r.kept = -1;
    }
    p->hot_used = hot;
    cnt[PC_STAT_CLIP_FALLBACKS] += r.fallback;
    cnt[PC_STAT_KEPT] += r.kept == 1;
    cnt[PC_STAT_KEPT_BROKEN] += r.kept == -1;
    if (r.status == PC_WORKSPACE) { cnt[PC_STAT_OVERFLOWS]++; p->vol = 0; memset(p->ft, 0, sizeof(p->ft)); return; }
    if (!(r.volume > 0)) {
        memset(p->ft, 0, sizeof(p->ft));
        if (!E->fast) { memcpy(p->axis, sep, sizeof(sep)); return; }
        /* apart: keep a proof for the next steps, from the separating face if
         * the tests found one, else a search from the last normal */
        double u[3], g;
        drop_axis(p);
        if (sep[0] != 0 || sep[1] != 0 || sep[2] != 0) {
            g = axis_gap(vi, nvi, vj, nvj, d, sep);
            if (g > margin) keep_axis(E, p, sep, g);
        } else if (!(searched_d && !hot) &&   /* from d again: the same search, the same failure */
                   find_axis(vi, nvi, vj, nvj, d, hot ? p->n : d, margin, PC_SEARCH_ITERATIONS, u, &g)) {
            keep_axis(E, p, u, g);
        }
        return;
    }
    drop_axis(p);
    p->touching = 1;
    p->vol = r.volume; p->area = r.area; p->fp[0] = r.footprint[0]; p->fp[1] = r.footprint[1];
    for (int c = 0; c < 3; c++) { p->c[c] = r.centroid[c] + E->x[3 * i + c]; p->n[c] = r.normal[c]; }
    double fn = E->kv * r.volume;
    p->fn[0] = fn * p->n[0]; p->fn[1] = fn * p->n[1]; p->fn[2] = fn * p->n[2];
    /* tangential */
    double dui[3], duj[3], du[3];
    point_disp(E, i, p->c, dui); point_disp(E, j, p->c, duj);
    du[0] = duj[0] - dui[0]; du[1] = duj[1] - dui[1]; du[2] = duj[2] - dui[2];
    double twist = 0.5 * (spin_about(E, i, p->n) + spin_about(E, j, p->n));
    double di = E->size[i], dj = E->size[j];
    double dp = (di + dj > 0) ? 2 * di * dj / (di + dj) : 0;
    double kt = E->ct * dp * dp;
    if (!hot) { du[0] = du[1] = du[2] = 0; twist = 0; }   /* a new contact starts unloaded */
    tangential(p->ft, p->n, twist, du, kt, E->mu, fn);
}

/* The overlap of body b with wall k at the last step's poses (r), and the
 * wall's inward normal n and the half-space offset used. */
static void wall_overlap(const engine_t *E, int b, int k, work_t *w, int want_shadow, overlap_t *r, double *n) {
    int ax = E->wall_axis[k];
    double gap = E->wall_sign[k] * (E->x[3 * b + ax] - E->wall_pos[k]);
    posed_t A = {E->voffb[b + 1] - E->voffb[b], E->toffb[b + 1] - E->toffb[b], E->rv + 3 * E->voffb[b],
                 E->T.t + 3 * E->T.toff[E->shape[b]], E->rn + 3 * E->toffb[b], E->rh + E->toffb[b], NULL, NULL, NULL,
                 {0, 0, 0}};
    posed_faces(&E->T, E->shape[b], &A);
    n[0] = n[1] = n[2] = 0;
    n[ax] = E->wall_sign[k];              /* clip keeps n.x <= h with n = m, h = m.(wall - x) = -gap */
    if (E->fast) overlap_halfspace_mesh(&A, n, -gap, w, want_shadow, r);
    else overlap_halfspace(&A, n, -gap, w, want_shadow, r);
}

/* One body against every wall. cnt: the thread's counters. */
static void walls_step(engine_t *E, int b, work_t *w, int *cnt) {
    int nw = E->nw;
    for (int k = 0; k < nw; k++) {
        int idx = b * nw + k;
        int whot = E->wtouch[idx];
        E->wtouch[idx] = 0;
        int ax = E->wall_axis[k];
        double sg = E->wall_sign[k];
        /* inward normal m = sg e_ax; body side: sg (x - wall) >= 0 */
        double gap = sg * (E->x[3 * b + ax] - E->wall_pos[k]);
        if (gap >= body_radius(E, b)) { memset(E->wft + 3 * idx, 0, 3 * sizeof(double)); continue; }
        const double *vb = E->rv + 3 * E->voffb[b];
        int nvb = E->voffb[b + 1] - E->voffb[b];
        double mn = INFINITY;
        for (int a = 0; a < nvb; a++) { double s = sg * vb[3 * a + ax]; if (s < mn) mn = s; }
        if (gap + mn >= 0) { memset(E->wft + 3 * idx, 0, 3 * sizeof(double)); continue; }
        double n[3];
        overlap_t r = {0};
        wall_overlap(E, b, k, w, !E->fast, &r, n);
        if (r.status == PC_WORKSPACE) { cnt[PC_STAT_OVERFLOWS]++; memset(E->wft + 3 * idx, 0, 3 * sizeof(double)); continue; }
        if (!(r.volume > 0)) { memset(E->wft + 3 * idx, 0, 3 * sizeof(double)); continue; }
        E->wtouch[idx] = 1;
        double *res = E->wres + PC_WALL_DOUBLES * idx;
        double fn = E->kv * r.volume;
        res[0] = r.volume;
        for (int c = 0; c < 3; c++) res[1 + c] = r.centroid[c] + E->x[3 * b + c];
        res[4] = r.footprint[0]; res[5] = r.footprint[1]; res[6] = r.area;
        /* force on the body by the wall: along m */
        for (int c = 0; c < 3; c++) res[7 + c] = fn * n[c];
        if (E->mu_wall > 0) {
            double du[3];
            point_disp(E, b, res + 1, du);      /* the wall's own motion is normal to it */
            if (!whot) { du[0] = du[1] = du[2] = 0; }
            double twist = spin_about(E, b, n) * 0.5;
            double kt = E->ct * E->size[b] * E->size[b];
            tangential(E->wft + 3 * idx, n, twist, du, kt, E->mu_wall, fn);
        } else {
            memset(E->wft + 3 * idx, 0, 3 * sizeof(double));
        }
    }
}

/* rotated vertices and normals of every body (body-centred); with motion,
 * also its spin and its motion bound over the last step (each body its own
 * entries: no order, no sharing) */
static void pose_all(engine_t *E, int par, int motion) {
    int nb = E->nb;
#ifdef _OPENMP
#pragma omp parallel for num_threads(E->nthreads) schedule(static) if (par)
#endif
    for (int b = 0; b < nb; b++) {
        posed_t P;
        double zero[3] = {0, 0, 0};
        pose_shape(&E->T, E->shape[b], E->R + 9 * b, zero, E->rv + 3 * E->voffb[b], E->rn + 3 * E->toffb[b],
                   E->rh + E->toffb[b], &P);
        E->ra[b] = posed_extent(&P);
        const table_t *T = &E->T;
        int s = E->shape[b];
        double *pn = E->rpn + 3 * E->poffb[b], *ph = E->rph + E->poffb[b];
        const double *rn = E->rn + 3 * E->toffb[b], *rh = E->rh + E->toffb[b];
        for (int p = 0; p < T->nface[s]; p++) {    /* the face planes pose_shape posed, contiguous */
            int t = T->ftag[T->foff[s] + p];
            memcpy(pn + 3 * p, rn + 3 * t, 3 * sizeof(double));
            ph[p] = rh[t];
        }
        if (motion) { E->motion[b] += body_motion(E, b); body_spin(E, b, E->spin + 3 * b); }
    }
}

/* One step. pos (nb,3), quat (nb,4) w,x,y,z; wall_pos (nw) coordinate of each
 * wall plane along its axis. Outputs: force, torque (nb,3) on the bodies,
 * wall_force (nw,3) on the walls; stat (PC_NSTAT): the step's counters,
 * named by pc_engine_stat_name. Returns 0, -1 (memory), -2 (non-finite
 * positions), -4 (a contact overflowed the clipping workspace: it would have
 * been lost; stat[PC_STAT_OVERFLOWS] counts them), -5 (an orientation
 * quaternion whose squared norm is zero, NaN, or outside [1e-200, 1e200]:
 * quat_to_mat would have taken it as the identity or lost it to round-off).
 * A refused step leaves the engine's state as it was. */
int pc_engine_step(engine_t *E, const double *pos, const double *quat, const double *wall_pos,
                   double *force, double *torque, double *wall_force, double *stat) {
    int nb = E->nb, nw = E->nw;
    for (int b = 0; b < 3 * nb; b++) if (!isfinite(pos[b])) return -2;
    for (int b = 0; b < nb; b++) {
        const double *q = quat + 4 * b;
        double s = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
        if (!(s >= 1e-200 && s <= 1e200)) return -5;
    }
    /* poses */
    if (E->have_prev) { memcpy(E->xprev, E->x, sizeof(double) * 3 * nb); memcpy(E->Rprev, E->R, sizeof(double) * 9 * nb); }
    memcpy(E->x, pos, sizeof(double) * 3 * nb);
    for (int b = 0; b < nb; b++) quat_to_mat(quat + 4 * b, E->R + 9 * b);
    if (!E->have_prev) { memcpy(E->xprev, E->x, sizeof(double) * 3 * nb); memcpy(E->Rprev, E->R, sizeof(double) * 9 * nb); }
    for (int k = 0; k < nw; k++) E->wall_pos[k] = wall_pos[k];
    E->shadows_ready = 0;
    /* Threads only when a step has enough work: a parallel region costs a
     * wake-up and a barrier (about 10-50 us with OMP_WAIT_POLICY=PASSIVE),
     * more than a small scene's whole step. */
    int par = E->nthreads > 1 && (E->npairs + nb * nw) >= E->parallel_min;
    pose_all(E, par, 1);
    /* neighbour list: rebuild when a body moved more than skin/2 */
    int need = E->npairs == 0 && E->nbuild == 0;
    double lim = 0.25 * E->skin * E->skin;
    for (int b = 0; b < nb && !need; b++) {
        double d[3] = {E->x[3 * b] - E->xbuild[3 * b], E->x[3 * b + 1] - E->xbuild[3 * b + 1], E->x[3 * b + 2] - E->xbuild[3 * b + 2]};
        if (dot3(d, d) > lim) need = 1;
    }
    if (need) { int e = rebuild(E); if (e) return e; }
    int cnt[PC_NSTAT];
    memset(cnt, 0, sizeof(cnt));
    par = E->nthreads > 1 && (E->npairs + nb * nw) >= E->parallel_min;
#ifdef _OPENMP
#pragma omp parallel num_threads(E->nthreads) if (par)
#endif
    {
        int tid = 0, mine[PC_NSTAT];
        memset(mine, 0, sizeof(mine));
#ifdef _OPENMP
        tid = omp_get_thread_num();
#endif
        work_t *w = &E->work[tid];
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 16) nowait
#endif
        for (int k = 0; k < E->npairs; k++) pair_step(E, E->pairs + k, w, mine);
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 16)
#endif
        for (int b = 0; b < E->nsolid; b++) walls_step(E, b, w, mine);   /* no wall pushes a facet */
        for (int k = 0; k < PC_NSTAT; k++) {
            if (!mine[k]) continue;
#ifdef _OPENMP
#pragma omp atomic
#endif
            cnt[k] += mine[k];
        }
    }
    /* forces and torques (serial: a sum per body, in a fixed order) */
    memset(force, 0, sizeof(double) * 3 * nb);
    memset(torque, 0, sizeof(double) * 3 * nb);
    memset(wall_force, 0, sizeof(double) * 3 * nw);
    double ntouch = 0, nslide = 0, sumF = 0, nwall = 0;
    for (int k = 0; k < E->npairs; k++) {
        pair_t *p = E->pairs + k;
        if (!p->touching) continue;
        ntouch++;
        double F[3] = {p->fn[0] + p->ft[0], p->fn[1] + p->ft[1], p->fn[2] + p->ft[2]};
        double fnm = sqrt(dot3(p->fn, p->fn));
        if (sqrt(dot3(p->ft, p->ft)) >= E->mu * fnm * (1 - 1e-12) && fnm > 0) nslide++;
        sumF += sqrt(dot3(F, F));
        int i = p->i, j = p->j;
        double ri[3] = {p->c[0] - E->x[3 * i], p->c[1] - E->x[3 * i + 1], p->c[2] - E->x[3 * i + 2]};
        double rj[3] = {p->c[0] - E->x[3 * j], p->c[1] - E->x[3 * j + 1], p->c[2] - E->x[3 * j + 2]};
        double ti[3], tj[3];
        cross3(rj, F, tj); cross3(ri, F, ti);
        for (int c = 0; c < 3; c++) {
            force[3 * j + c] += F[c]; force[3 * i + c] -= F[c];
            torque[3 * j + c] += tj[c]; torque[3 * i + c] -= ti[c];
        }
    }
    for (int b = 0; b < nb; b++) for (int k = 0; k < nw; k++) {
        int idx = b * nw + k;
        if (!E->wtouch[idx]) continue;
        nwall++;
        double *res = E->wres + PC_WALL_DOUBLES * idx, *ft = E->wft + 3 * idx;
        double F[3] = {res[7] + ft[0], res[8] + ft[1], res[9] + ft[2]};
        sumF += sqrt(dot3(F, F));
        double r[3] = {res[1] - E->x[3 * b], res[2] - E->x[3 * b + 1], res[3] - E->x[3 * b + 2]}, t[3];
        cross3(r, F, t);
        for (int c = 0; c < 3; c++) { force[3 * b + c] += F[c]; torque[3 * b + c] += t[c]; wall_force[3 * k + c] -= F[c]; }
    }
    double sumB = 0;
    for (int b = 0; b < nb; b++) sumB += sqrt(dot3(force + 3 * b, force + 3 * b));
    E->have_prev = 1;
    E->shadows_ready = !E->fast;
    for (int k = 0; k < PC_NSTAT; k++) E->stat[k] = cnt[k];
    E->stat[PC_STAT_TOUCHING_PAIRS] = ntouch; E->stat[PC_STAT_WALL_CONTACTS] = nwall;
    E->stat[PC_STAT_LISTED_PAIRS] = E->npairs; E->stat[PC_STAT_SLIDING] = nslide;
    E->stat[PC_STAT_SUM_CONTACT_FORCE] = sumF; E->stat[PC_STAT_REBUILDS] = (double)E->nbuild;
    E->stat[PC_STAT_SUM_BODY_FORCE] = sumB;
    if (stat) memcpy(stat, E->stat, sizeof(E->stat));
    return cnt[PC_STAT_OVERFLOWS] ? -4 : 0;
}

/* The shadows (footprint, area) of the last step's contacts, if not yet
 * computed: the same clipping again on the same poses, path and plane order,
 * so the polygons are those the step's volumes came from. */
static void ensure_shadows(engine_t *E) {
    if (E->shadows_ready) return;
    int nb = E->nb, nw = E->nw;
    int par = E->nthreads > 1 && (E->npairs + nb * nw) >= E->parallel_min;
#ifdef _OPENMP
#pragma omp parallel num_threads(E->nthreads) if (par)
#endif
    {
        int tid = 0;
#ifdef _OPENMP
        tid = omp_get_thread_num();
#endif
        work_t *w = &E->work[tid];
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 16) nowait
#endif
        for (int k = 0; k < E->npairs; k++) {
            pair_t *p = E->pairs + k;
            if (!p->touching) continue;
            int i = p->i, j = p->j;
            double d[3] = {E->x[3 * j] - E->x[3 * i], E->x[3 * j + 1] - E->x[3 * i + 1], E->x[3 * j + 2] - E->x[3 * i + 2]};
            posed_t A, B;
            pose_pair(E, i, j, d, w, &A, &B, NULL);
            overlap_t r = {0};
            overlap_pair(&A, &B, d, w, &r, NULL, p->hot_used, E->fast, 1, NULL);
            p->fp[0] = r.footprint[0]; p->fp[1] = r.footprint[1]; p->area = r.area;
        }
#ifdef _OPENMP
#pragma omp for schedule(dynamic, 16)
#endif
        for (int b = 0; b < nb; b++) for (int k = 0; k < nw; k++) {
            int idx = b * nw + k;
            if (!E->wtouch[idx]) continue;
            double n[3], *res = E->wres + PC_WALL_DOUBLES * idx;
            overlap_t r = {0};
            wall_overlap(E, b, k, w, 1, &r, n);
            res[4] = r.footprint[0]; res[5] = r.footprint[1]; res[6] = r.area;
        }
    }
    E->shadows_ready = 1;
}

/* number of touching contacts (particle pairs, then body-wall) of the last step */
int pc_engine_count(const engine_t *E) {
    int n = 0;
    for (int k = 0; k < E->npairs; k++) n += E->pairs[k].touching;
    for (int k = 0; k < E->nb * E->nw; k++) n += E->wtouch[k];
    return n;
}

/* The contacts of the last step, at most cap: body rows i1, i2, point (3),
 * normal (3, from i1 to i2), normal force on i2 (3), tangential force on i2
 * (3), volume, footprint (2), area. For a wall contact i1 = -1 - k (wall k)
 * and i2 = the body row; the normal points from the wall into the box.
 * Returns the number written. */
int pc_engine_contacts(engine_t *E, int cap, int *i1, int *i2, double *point, double *normal,
                       double *fnrm, double *ftan, double *vol, double *fp, double *area) {
    ensure_shadows(E);
    int m = 0;
    for (int k = 0; k < E->npairs && m < cap; k++) {
        const pair_t *p = E->pairs + k;
        if (!p->touching) continue;
        i1[m] = p->i; i2[m] = p->j;
        for (int c = 0; c < 3; c++) { point[3 * m + c] = p->c[c]; normal[3 * m + c] = p->n[c]; fnrm[3 * m + c] = p->fn[c]; ftan[3 * m + c] = p->ft[c]; }
        vol[m] = p->vol; fp[2 * m] = p->fp[0]; fp[2 * m + 1] = p->fp[1]; area[m] = p->area;
        m++;
    }
    for (int b = 0; b < E->nb; b++) for (int k = 0; k < E->nw && m < cap; k++) {
        int idx = b * E->nw + k;
        if (!E->wtouch[idx]) continue;
        const double *res = E->wres + PC_WALL_DOUBLES * idx, *ft = E->wft + 3 * idx;
        i1[m] = -1 - k; i2[m] = b;
        double n[3] = {0, 0, 0};
        n[E->wall_axis[k]] = E->wall_sign[k];
        for (int c = 0; c < 3; c++) { point[3 * m + c] = res[1 + c]; normal[3 * m + c] = n[c]; fnrm[3 * m + c] = res[7 + c]; ftan[3 * m + c] = ft[c]; }
        vol[m] = res[0]; fp[2 * m] = res[4]; fp[2 * m + 1] = res[5]; area[m] = res[6];
        m++;
    }
    return m;
}

/* The contacts of the last step as pc_engine_contacts gives them, without
 * the shadows (footprint, area), which cost a second clipping: body rows i1,
 * i2, point (3), normal (3, from i1 to i2), normal and tangential force on
 * i2 (3 each), volume; a wall contact has i1 = -1 - k. Returns the number
 * written (at most cap). */
int pc_engine_contacts_noshadow(engine_t *E, int cap, int *i1, int *i2, double *point, double *normal,
                                double *fnrm, double *ftan, double *vol) {
    int m = 0;
    for (int k = 0; k < E->npairs && m < cap; k++) {
        const pair_t *p = E->pairs + k;
        if (!p->touching) continue;
        i1[m] = p->i; i2[m] = p->j;
        for (int c = 0; c < 3; c++) { point[3 * m + c] = p->c[c]; normal[3 * m + c] = p->n[c]; fnrm[3 * m + c] = p->fn[c]; ftan[3 * m + c] = p->ft[c]; }
        vol[m] = p->vol;
        m++;
    }
    for (int b = 0; b < E->nb; b++) for (int k = 0; k < E->nw && m < cap; k++) {
        int idx = b * E->nw + k;
        if (!E->wtouch[idx]) continue;
        const double *res = E->wres + PC_WALL_DOUBLES * idx, *ft = E->wft + 3 * idx;
        i1[m] = -1 - k; i2[m] = b;
        double n[3] = {0, 0, 0};
        n[E->wall_axis[k]] = E->wall_sign[k];
        for (int c = 0; c < 3; c++) { point[3 * m + c] = res[1 + c]; normal[3 * m + c] = n[c]; fnrm[3 * m + c] = res[7 + c]; ftan[3 * m + c] = ft[c]; }
        vol[m] = res[0];
        m++;
    }
    return m;
}

/* Memory held by the engine (bytes), for the benchmark. */
long pc_engine_memory(const engine_t *E) {
    long b = sizeof(engine_t);
    b += (long)E->cap_pairs * sizeof(pair_t) + (long)E->cap_spare * sizeof(pair_t);
    b += (long)E->nb * (9 * 2 + 3 * 3 + 4) * sizeof(double);
    b += (long)(E->voffb[E->nb] * 3 + E->toffb[E->nb] * 4) * sizeof(double);
    b += (long)E->nb * E->nw * (PC_WALL_DOUBLES + 4) * sizeof(double);
    for (int k = 0; k < E->nthreads; k++) {
        const work_t *w = &E->work[k];
        b += 2L * w->alloc_pts * 3 * sizeof(double) + 6L * w->cap_poly * sizeof(int) + w->alloc_pts * 3L * sizeof(double);
    }
    return b;
}

/* Set the shear history of the touching pair (i, j) (tests). Returns 0 if found. */
int pc_engine_set_history(engine_t *E, int i, int j, const double *ft) {
    for (int k = 0; k < E->npairs; k++)
        if (E->pairs[k].i == i && E->pairs[k].j == j) { memcpy(E->pairs[k].ft, ft, 3 * sizeof(double)); return 0; }
    return -1;
}

/* Give the bodies groups (group[b], per body row; -1: none; NULL: no
 * groups, as a new engine has): two bodies of one group >= 0 (the members
 * of a YADE clump, which move as one rigid body) are never a pair, as YADE's
 * collider never makes an interaction between members of one clump. The
 * pairs of one group already listed are dropped now (from a state carried
 * over), later lists skip them. Returns 0, or -1 when memory could not be
 * had (the groups then unchanged). */
int pc_engine_set_groups(engine_t *E, const int *group) {
    if (!group) { free(E->group); E->group = NULL; return 0; }
    int *g = malloc(sizeof(int) * (E->nb + 1));
    if (!g) return -1;
    memcpy(g, group, sizeof(int) * E->nb);
    free(E->group);
    E->group = g;
    drop_never_pairs(E);
    return 0;
}

/* Rows n .. nb - 1 are facets from now on (a user scene's, after its
 * polyhedra): two facets are never a pair and no wall pushes a facet (YADE
 * has neither a facet-facet nor a wall-facet functor). The listed pairs of
 * two facets and the facets' wall contacts are dropped at once. Returns 0,
 * or -1 for n outside 0 .. nb. */
int pc_engine_set_facets(engine_t *E, int n) {
    if (n < 0 || n > E->nb) return -1;
    E->nsolid = n;
    size_t a = (size_t)n * E->nw, z = (size_t)E->nb * E->nw;
    if (z > a) {
        memset(E->wtouch + a, 0, sizeof(int) * (z - a));
        memset(E->wft + 3 * a, 0, sizeof(double) * 3 * (z - a));
        memset(E->wres + (size_t)PC_WALL_DOUBLES * a, 0, sizeof(double) * PC_WALL_DOUBLES * (z - a));
    }
    drop_never_pairs(E);
    return 0;
}

/* Change the friction coefficients between steps (e.g. frictionless
 * compaction, then mu before shear). Histories above the new cap are cut to
 * it at the next step. Returns 0, or -1 for a negative or non-finite value. */
int pc_engine_set_friction(engine_t *E, double mu, double mu_wall) {
    if (!(mu >= 0 && mu_wall >= 0 && isfinite(mu) && isfinite(mu_wall))) return -1;
    E->mu = mu; E->mu_wall = mu_wall;
    return 0;
}

void pc_engine_get_friction(const engine_t *E, double *mu) { mu[0] = E->mu; mu[1] = E->mu_wall; }

/* The path of the next steps: 1 (default) proofs of separation, culled
 * clipping and shadows on demand; 0 the plain path (every listed pair
 * tested by faces and clipped, shadows every step), kept to check the fast
 * one against. Both give the same contacts and forces (tested). */
void pc_engine_set_mode(engine_t *E, int fast) {
    E->fast = fast ? 1 : 0;
    if (!E->fast) for (int k = 0; k < E->npairs; k++) drop_axis(E->pairs + k);   /* the plain path's axes are face normals */
}

/* Shrink the clipping workspaces to npts points (tests: force an
 * overflow; the shared-vertex cuts then give up and the polygon clipping
 * overflows). Returns 0, or -1 for more than was allocated or fewer than 16. */
int pc_engine_set_workspace_points(engine_t *E, int npts) {
    for (int k = 0; k < E->nthreads; k++) if (npts > E->work[k].alloc_pts || npts < 16) return -1;
    for (int k = 0; k < E->nthreads; k++) {
        work_t *w = &E->work[k];
        w->cap_pts = npts;
        w->cap_mv = npts < w->alloc_mv ? npts : w->alloc_mv;
    }
    return 0;
}

/* The sizes of the records the Python side allocates: [0] doubles per pair
 * record of the state, [1] doubles per wall contact's results, [2] step
 * counters, [3] state scalars, [4] walls at most. */
void pc_engine_layout(int *out) {
    out[0] = PC_PAIR_DOUBLES; out[1] = PC_WALL_DOUBLES; out[2] = PC_NSTAT; out[3] = PC_SCALARS; out[4] = PC_MAX_WALLS;
}

/* The name of step counter k (see PC_STAT_*), or NULL. */
const char *pc_engine_stat_name(int k) { return k >= 0 && k < PC_NSTAT ? PC_STAT_NAMES[k] : NULL; }

/* ================================================================== engine state (checkpoints) */
/* Everything a later step depends on, so that an engine restored from it
 * continues bit for bit like the original: the last poses (x, R), the
 * neighbour list's reference positions, every body's motion bound, every
 * listed pair (ids, shear history, cached separating axis with its gap and
 * motion bounds, touched flag, clipping path, last results), the wall
 * contacts' histories, flags and results, and the counters and wall
 * positions. Pair records are PC_PAIR_DOUBLES doubles:
 * ft(3) axis(3) vol c(3) n(3) fp(2) area fn(3) touching gap mi0 mj0 hot_used,
 * then the kept structure, its bytes 6 to a double (whole numbers below
 * 2^48, exact in any float64 store). */
static void keep_pack(const keep_t *K, double *r) {
    const unsigned char *b = (const unsigned char *)K;
    for (int k = 0; k < PC_KEEP_DOUBLES; k++) {
        double x = 0;
        for (int c = 5; c >= 0; c--) { size_t i = 6 * (size_t)k + c; x = x * 256 + (i < sizeof(keep_t) ? b[i] : 0); }
        r[k] = x;
    }
}

static int keep_unpack(const double *r, keep_t *K) {
    unsigned char *b = (unsigned char *)K;
    for (int k = 0; k < PC_KEEP_DOUBLES; k++) {
        double x = r[k];
        if (!(x >= 0 && x < 281474976710656.0) || x != floor(x)) return -1;
        for (int c = 0; c < 6; c++) {
            size_t i = 6 * (size_t)k + c;
            double q = floor(x / 256);
            if (i < sizeof(keep_t)) b[i] = (unsigned char)(x - 256 * q);
            x = q;
        }
    }
    if (K->ok > 1 || K->nv > PC_KV || K->nf > PC_KF || K->ni > PC_KI) return -1;
    return 0;
}
int pc_engine_npairs(const engine_t *E) { return E->npairs; }

void pc_engine_get_state(engine_t *E, double *x, double *R, double *xbuild, double *motion, int *ij, double *prec,
                         double *wft, double *wres, int *wtouch, double *scalars) {
    int nb = E->nb, nw = E->nw;
    if (E->have_prev) ensure_shadows(E);
    memcpy(x, E->x, sizeof(double) * 3 * nb);
    memcpy(R, E->R, sizeof(double) * 9 * nb);
    memcpy(xbuild, E->xbuild, sizeof(double) * 3 * nb);
    memcpy(motion, E->motion, sizeof(double) * nb);
    for (int k = 0; k < E->npairs; k++) {
        const pair_t *p = E->pairs + k;
        double *r = prec + PC_PAIR_DOUBLES * k;
        ij[2 * k] = p->i; ij[2 * k + 1] = p->j;
        memcpy(r, p->ft, 3 * sizeof(double)); memcpy(r + 3, p->axis, 3 * sizeof(double));
        r[6] = p->vol; memcpy(r + 7, p->c, 3 * sizeof(double)); memcpy(r + 10, p->n, 3 * sizeof(double));
        memcpy(r + 13, p->fp, 2 * sizeof(double)); r[15] = p->area; memcpy(r + 16, p->fn, 3 * sizeof(double));
        r[19] = p->touching; r[20] = p->gap; r[21] = p->mi0; r[22] = p->mj0; r[23] = p->hot_used;
        keep_pack(&p->keep, r + 24);
    }
    memcpy(wft, E->wft, sizeof(double) * 3 * nb * nw);
    memcpy(wres, E->wres, sizeof(double) * PC_WALL_DOUBLES * nb * nw);
    memcpy(wtouch, E->wtouch, sizeof(int) * nb * nw);
    memset(scalars, 0, sizeof(double) * PC_SCALARS);
    scalars[0] = E->have_prev; scalars[1] = (double)E->nbuild;
    for (int k = 0; k < nw; k++) scalars[2 + k] = E->wall_pos[k];
}

/* Restore a state taken by pc_engine_get_state from an engine built with the
 * same shapes, bodies and walls. Returns 0, -1 (memory) or -3 (a pair id out
 * of range or not sorted: not a state of this engine). */
int pc_engine_set_state(engine_t *E, const double *x, const double *R, const double *xbuild, const double *motion,
                        int npairs, const int *ij, const double *prec, const double *wft, const double *wres,
                        const int *wtouch, const double *scalars) {
    int nb = E->nb, nw = E->nw;
    for (int k = 0; k < npairs; k++) {
        int i = ij[2 * k], j = ij[2 * k + 1];
        if (i < 0 || j <= i || j >= nb) return -3;
        keep_t K;
        if (keep_unpack(prec + PC_PAIR_DOUBLES * k + 24, &K)) return -3;
        if (k > 0 && (ij[2 * k - 2] > i || (ij[2 * k - 2] == i && ij[2 * k - 1] >= j))) return -3;
    }
    if (npairs > E->cap_pairs) {
        pair_t *p = realloc(E->pairs, sizeof(pair_t) * (npairs + 1));
        if (!p) return -1;
        E->pairs = p; E->cap_pairs = npairs + 1;
    }
    memcpy(E->x, x, sizeof(double) * 3 * nb);
    memcpy(E->R, R, sizeof(double) * 9 * nb);
    memcpy(E->xbuild, xbuild, sizeof(double) * 3 * nb);
    memcpy(E->motion, motion, sizeof(double) * nb);
    E->npairs = npairs;
    for (int k = 0; k < npairs; k++) {
        pair_t *p = E->pairs + k;
        const double *r = prec + PC_PAIR_DOUBLES * k;
        memset(p, 0, sizeof(*p));
        p->i = ij[2 * k]; p->j = ij[2 * k + 1];
        memcpy(p->ft, r, 3 * sizeof(double)); memcpy(p->axis, r + 3, 3 * sizeof(double));
        p->vol = r[6]; memcpy(p->c, r + 7, 3 * sizeof(double)); memcpy(p->n, r + 10, 3 * sizeof(double));
        memcpy(p->fp, r + 13, 2 * sizeof(double)); p->area = r[15]; memcpy(p->fn, r + 16, 3 * sizeof(double));
        p->touching = r[19] != 0; p->gap = r[20]; p->mi0 = r[21]; p->mj0 = r[22]; p->hot_used = r[23] != 0;
        keep_unpack(r + 24, &p->keep);
    }
    memcpy(E->wft, wft, sizeof(double) * 3 * nb * nw);
    memcpy(E->wres, wres, sizeof(double) * PC_WALL_DOUBLES * nb * nw);
    memcpy(E->wtouch, wtouch, sizeof(int) * nb * nw);
    E->have_prev = scalars[0] != 0;
    E->nbuild = (long)scalars[1];
    for (int k = 0; k < nw; k++) E->wall_pos[k] = scalars[2 + k];
    pose_all(E, 0, 0);              /* the posed vertices of these poses (contacts can be asked for at once) */
    E->shadows_ready = 1;           /* the records carry the shadows */
    return 0;
}
