/*
 * rr_fastsim_kernel.h - FASTSIM's vector kernels, written once for any
 * vector width.  Not a header of its own: rr_fastsim.c includes it once per
 * vector type, after the march, group and sums types, GROUP_VECS and
 * RR_FASTSIM_INLINE, with
 *   V        the vector's prefix: v2 or v4 (type V, operations V_add, ...)
 *   V_LANES  the doubles in one V
 *   V_FN     what precedes every function: static, and where needed a
 *            function-level target (AVX) so that no build flag must change
 * Every function's name ends in _V (group_coulomb_v2, ...).  Each lane does
 * exactly the IEEE operations of the scalar march, whatever the width.
 */

#define V_CAT_(a, b) a##b
#define V_CAT(a, b) V_CAT_(a, b)
#define V_NAME(name) V_CAT(name, V_CAT(_, V))

#define vec V
#define v_set1 V_CAT(V, _set1)
#define v_add V_CAT(V, _add)
#define v_sub V_CAT(V, _sub)
#define v_mul V_CAT(V, _mul)
#define v_div V_CAT(V, _div)
#define v_sqrt V_CAT(V, _sqrt)
#define v_max V_CAT(V, _max)
#define v_load V_CAT(V, _load)
#define v_store V_CAT(V, _store)

/* Element positions of a step i for nv vectors of rows: x = ((nx - 1)/2 - i)
 * h (elem_q's), (x/a)^2 and the rigid slip (gy + gphi x) h.  On the
 * rectangular grid every row has the same elements (h = 2a/nx), so the
 * first vector's serve all. */
V_FN RR_FASTSIM_INLINE void V_NAME(step_geometry)(const march *m, const vec *h,
                                                  int nv, int rect, int slip_too, int i,
                                                  vec *x, vec *tt, vec *vy)
{
    const vec xi = v_set1(0.5 * (m->nx - 1) - i), inv_a = v_set1(m->inv_a);
    const vec gy = v_set1(m->gy), gphi = v_set1(m->gphi);
    int v;
    for (v = 0; v < (rect ? 1 : nv); v++) {
        const vec xv = v_mul(xi, h[v]), t = v_mul(xv, inv_a);
        x[v] = xv;
        tt[v] = v_mul(t, t);
        if (slip_too)
            vy[v] = v_mul(v_add(gy, v_mul(gphi, xv)), h[v]);
    }
    for (; v < nv; v++) {
        x[v] = x[0];
        tt[v] = tt[0];
        if (slip_too)
            vy[v] = vy[0];
    }
}

/* Sum of q (parabolic) or sqrt(q) over the inside elements of each row of
 * the group, for the pressure scale.  An element outside adds +0, which
 * changes no sum (a sum that starts at +0 never becomes -0).  Elements i
 * and nx - 1 - i lie at -x and x: the left half's values are taken twice. */
V_FN RR_FASTSIM_INLINE void V_NAME(group_pressure)(const march *m, const group *g, int nv,
                                                   int rect, double *rows)
{
    vec h[GROUP_VECS], w2[GROUP_VECS], acc[GROUP_VECS];
    const vec zero = v_set1(0.0);
    int i, v;
    for (v = 0; v < nv; v++) {
        h[v] = v_load(g->h + V_LANES * v);
        w2[v] = v_load(g->w2 + V_LANES * v);
        acc[v] = zero;
    }
    const int lo = g->lo < m->nx - g->hi ? g->lo : m->nx - g->hi, mid = m->nx / 2;
    for (i = lo; i < mid + m->nx % 2; i++) {
        vec x[GROUP_VECS], tt[GROUP_VECS];
        V_NAME(step_geometry)(m, h, nv, rect, 0, i, x, tt, 0);
        for (v = 0; v < nv; v++) {
            const vec q = v_max(v_sub(w2[v], tt[v]), zero), r = m->parabolic ? q : v_sqrt(q);
            acc[v] = v_add(acc[v], i < mid ? v_add(r, r) : r);
        }
    }
    for (v = 0; v < nv; v++)
        v_store(rows + V_LANES * v, acc[v]);
}

/* The march of a group with one friction coefficient over the patch
 * (Coulomb, or falling friction at the rigid slip speed), nv vectors of
 * rows side by side, without a branch or a comparison; the element count
 * nslip is not kept.  With g = mu pn and t* the trial traction, the
 * element's traction is t* g / max(|t*|, g): for |t*|^2 > g^2 (the march's
 * test for slip) that is t* g/|t*|, the very quotient of group_march, and
 * otherwise t* g/g = t* exactly, because sqrt(g*g) == g in binary floating
 * point (sqrt and * correctly rounded; g*g neither underflows nor
 * overflows, which march_in_range guarantees).  Outside the ellipse
 * max(q, 0) = 0 makes g = 0 and the traction +-0: that adds +-0 to the
 * sums, which changes none of them (a sum that starts at +0 never becomes
 * -0), and enters the next element's trial traction only as a zero; so each
 * row adds exactly what its own march adds. */
V_FN RR_FASTSIM_INLINE void V_NAME(group_coulomb)(const march *m, const group *g, int nv,
                                                  int rect, sums *s)
{
    vec h[GROUP_VECS], w2[GROUP_VECS], y[GROUP_VECS], gxh[GROUP_VECS];
    vec px[GROUP_VECS], py[GROUP_VECS], sx[GROUP_VECS], sy[GROUP_VECS], sm[GROUP_VECS];
    const vec zero = v_set1(0.0), tiny = v_set1(DBL_MIN);
    const vec scale = v_set1(m->scale), mu = v_set1(m->mu_bound);
    int i, v;
    for (v = 0; v < nv; v++) {
        h[v] = v_load(g->h + V_LANES * v);
        w2[v] = v_load(g->w2 + V_LANES * v);
        y[v] = v_load(g->y + V_LANES * v);
        gxh[v] = v_load(g->gxh + V_LANES * v);
        px[v] = py[v] = sx[v] = sy[v] = sm[v] = zero;
    }
    for (i = g->lo; i < g->hi; i++) {
        vec x[GROUP_VECS], tt[GROUP_VECS], vy[GROUP_VECS];
        V_NAME(step_geometry)(m, h, nv, rect, 1, i, x, tt, vy);
        for (v = 0; v < nv; v++) {
            const vec q = v_max(v_sub(w2[v], tt[v]), zero);
            const vec gb = v_mul(mu, v_mul(scale, m->parabolic ? q : v_sqrt(q)));
            const vec tx = v_sub(px[v], gxh[v]), ty = v_sub(py[v], vy[v]);
            const vec mag = v_sqrt(v_add(v_mul(tx, tx), v_mul(ty, ty)));
            /* max(g, DBL_MIN): no 0/0 outside the ellipse */
            const vec r = v_div(gb, v_max(mag, v_max(gb, tiny)));
            px[v] = v_mul(tx, r);
            py[v] = v_mul(ty, r);
            sx[v] = v_add(sx[v], px[v]);
            sy[v] = v_add(sy[v], py[v]);
            sm[v] = v_add(sm[v], v_sub(v_mul(x[v], py[v]), v_mul(y[v], px[v])));
        }
    }
    for (v = 0; v < nv; v++) {
        v_store(s->sx + V_LANES * v, sx[v]);
        v_store(s->sy + V_LANES * v, sy[v]);
        v_store(s->sm + V_LANES * v, sm[v]);
    }
    s->nslip = 0;
    s->converged = 1;
}

/* The kernels for the group's width and grid, each compiled for its own
 * fixed number of vectors. */
#if GROUP_VECS != 5
#error "V_FIXED has a kernel for each of 1 .. 5 vectors"
#endif
#define V_FIXED(kernel, m, g, out)                                                    \
    do {                                                                             \
        const int nv_ = (g)->width / V_LANES, rect_ = !(m)->strips;                  \
        if (nv_ == 5) {                                                              \
            if (rect_) kernel(m, g, 5, 1, out); else kernel(m, g, 5, 0, out);         \
        } else if (nv_ == 4) {                                                       \
            if (rect_) kernel(m, g, 4, 1, out); else kernel(m, g, 4, 0, out);         \
        } else if (nv_ == 3) {                                                       \
            if (rect_) kernel(m, g, 3, 1, out); else kernel(m, g, 3, 0, out);         \
        } else if (nv_ == 2) {                                                       \
            if (rect_) kernel(m, g, 2, 1, out); else kernel(m, g, 2, 0, out);         \
        } else {                                                                     \
            if (rect_) kernel(m, g, 1, 1, out); else kernel(m, g, 1, 0, out);         \
        }                                                                            \
    } while (0)

V_FN void V_NAME(pressure_dispatch)(const march *m, const group *g, double *rows)
{
    V_FIXED(V_NAME(group_pressure), m, g, rows);
}

V_FN void V_NAME(coulomb_dispatch)(const march *m, const group *g, sums *s)
{
    V_FIXED(V_NAME(group_coulomb), m, g, s);
}

#undef V_FIXED
#undef vec
#undef v_set1
#undef v_add
#undef v_sub
#undef v_mul
#undef v_div
#undef v_sqrt
#undef v_max
#undef v_load
#undef v_store
#undef V_NAME
#undef V_CAT
#undef V_CAT_
