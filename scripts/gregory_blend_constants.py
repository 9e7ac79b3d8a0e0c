# The constants of techniques/common/curvature_bounds.h (kGregoryQuadBlend,
# kGregoryTriangleBlend): sup over the domain of |second derivatives| of the Gregory blend
# functions g_c = B_c(u, v) (a - b) / (a + b), by rigorous interval branch and bound in
# (r, s) = (a + b, a / (a + b)), where g's second derivatives are polynomials (asserted
# below). Prints per case: the best value found at a point, and the proven upper bound.
# Usage: python3 scripts/gregory_blend_constants.py [tolerance, default 1e-3]
# (sympy; several minutes; corners 2 and 3 of the quad only repeat corners 0 and 1).
# python3 scripts/gregory_blend_constants.py --quadrants 10: the quad corner 0's g_0 on
# the quadrants u in [1/2, 1] x v in [0, 1/2] (10) and [1/2, 1]^2 (11), away from the corner,
# by the same branch and bound directly in (u, v) (g_0's second derivatives are N / (u + v)^k
# there, smooth; 10 only: --far-quadrant bounds 11 in (1 - u, 1 - v), tolerance 2e-2, and
# its uv did not finish within 10 minutes); quadrant 00 is bounded by the whole domain's, 01
# is 10 with uu and vv swapped.
import sympy as sp
from fractions import Fraction as F
import heapq, sys
TOL = float(sys.argv[1]) if len(sys.argv) > 1 and not sys.argv[1].startswith('--') else 1e-3
u, v, r, s = sp.symbols('u v r s')

def quad_cases():
    B = lambda i, x: [ (1-x)**3, 3*x*(1-x)**2, 3*x**2*(1-x), x**3][i]
    return [  # (basis, a, b, substitution u,v in r,s, region)
        (B(1,u)*B(1,v), u, v), (B(2,u)*B(1,v), v, 1-u),
        (B(2,u)*B(2,v), 1-u, 1-v), (B(1,u)*B(2,v), 1-v, u)]
def tri_cases():
    w = 1-u-v
    return [(12*u**2*v*w, v, w), (12*u*v**2*w, w, u), (12*u*v*w**2, u, v)]

def interval_pow(lo, hi, k):
    if k == 0: return (F(1), F(1))
    cands = [lo**k, hi**k]
    if k % 2 == 0 and lo < 0 < hi: cands.append(F(0))
    return (min(cands), max(cands))

def poly_range(terms, rlo, rhi, slo, shi):
    lo = hi = F(0)
    for (i, j), c in terms:
        a = interval_pow(rlo, rhi, i); b = interval_pow(slo, shi, j)
        prods = [x*y for x in a for y in b]
        pl, ph = min(prods), max(prods)
        if c >= 0: lo += c*pl; hi += c*ph
        else: lo += c*ph; hi += c*pl
    return lo, hi

def sup_abs(poly, region_ok, rmax, tol):
    P = sp.Poly(sp.expand(poly), r, s)
    terms = [((m[0], m[1]), F(int(sp.fraction(c)[0]), int(sp.fraction(c)[1]))) for m, c in zip(P.monoms(), P.coeffs())]
    f = sp.lambdify((r, s), poly)
    best = 0.0
    # lower bound from a coarse grid inside the region
    n = 200
    for i in range(n+1):
        for j in range(n+1):
            rr, ss = rmax*i/n, j/n
            if region_ok(rr, ss, rr, ss): best = max(best, abs(f(rr, ss)))
    heap = [(-1e300, F(0), F(rmax), F(0), F(1))]
    upper = 0.0
    count = 0
    while heap:
        negub, rlo, rhi, slo, shi = heapq.heappop(heap)
        lo, hi = poly_range(terms, rlo, rhi, slo, shi)
        ub = float(max(abs(lo), abs(hi)))
        if ub <= best + tol:
            upper = max(upper, ub); continue
        rm, sm = (rlo+rhi)/2, (slo+shi)/2
        # evaluate centre (inside region) to raise the lower bound
        if region_ok(float(rm), float(sm), float(rm), float(sm)): best = max(best, abs(f(float(rm), float(sm))))
        for a, b in ((rlo, rm), (rm, rhi)):
            for c, d in ((slo, sm), (sm, shi)):
                if region_ok(float(a), float(c), float(a), float(d)) or region_ok(float(a), float(d), float(a), float(d)) or region_ok(float(a),float(c)/2+float(d)/2,0,0):
                    heapq.heappush(heap, (-ub, a, b, c, d))
        count += 1
        if count > 400000: raise SystemExit('too many boxes')
    return best, max(upper, best)

def run(cases, quad):
    out = []
    for c, (basis, a, b) in enumerate(cases):
        g = basis*(a-b)/(a+b)
        # solve a = r s, b = r (1 - s) for u, v
        sol = sp.solve([sp.Eq(a, r*s), sp.Eq(b, r*(1-s))], [u, v], dict=True)[0]
        row = []
        for name, d in (('uu', sp.diff(g, u, 2)), ('uv', sp.diff(g, u, v)), ('vv', sp.diff(g, v, 2))):
            e = sp.cancel(sp.together(d.subs(sol)))
            num, den = sp.fraction(e)
            assert den.free_symbols == set(), (name, den)
            e = sp.expand(num/den)
            if quad:
                ok = lambda r0, s0, *_: r0*s0 <= 1 + 1e-12 and r0*(1-s0) <= 1 + 1e-12
                rmax = 2
            else:
                ok = lambda r0, s0, *_: r0 <= 1
                rmax = 1
            # box test: keep box if its low-r corner row could be in region (conservative)
            def region_box(rl, sl, rl2, sh):
                return ok(rl, sl) or ok(rl, sh)
            lo_, up_ = sup_abs(e, region_box, rmax, TOL)
            row.append((name, lo_, up_))
            print('quad' if quad else 'tri', c, name, lo_, up_, flush=True)
        out.append(row)
    return out

def quadrants():
    TOL = F(2, 1000)
    g = 9*u*(1-u)**2*v*(1-v)**2*(u-v)/(u+v)
    def ipow(lo, hi, k):
        return (lo**k, hi**k)  # lo >= 0
    for q in sys.argv[2:]:
        qa, qb = int(q[0]), int(q[1])
        U0, V0 = F(qa, 2), F(qb, 2)
        for name, d in (('uu', sp.diff(g, u, 2)), ('uv', sp.diff(g, u, v)), ('vv', sp.diff(g, v, 2))):
            num, den = sp.fraction(sp.factor(sp.together(d)))
            den = sp.factor(den)
            # den = (u+v)^k
            k = sp.degree(den, u)
            assert sp.expand(den - (u+v)**k) == 0, den
            P = sp.Poly(sp.expand(num), u, v)
            terms = [(m, F(int(sp.fraction(c)[0]), int(sp.fraction(c)[1]))) for m, c in zip(P.monoms(), P.coeffs())]
            fn = sp.lambdify((u, v), d)
            def rng(ulo, uhi, vlo, vhi):
                lo = hi = F(0)
                for (i, j), c in terms:
                    a0, a1 = ipow(ulo, uhi, i); b0, b1 = ipow(vlo, vhi, j)
                    pl, ph = a0*b0, a1*b1
                    if c >= 0: lo += c*pl; hi += c*ph
                    else: lo += c*ph; hi += c*pl
                dlo, dhi = (ulo+vlo)**k, (uhi+vhi)**k
                cands = [lo/dlo, lo/dhi, hi/dlo, hi/dhi]
                return max(abs(x) for x in cands) if not (lo <= 0 <= hi) else max(abs(lo/dlo), abs(hi/dlo))
            best = F(0)
            n = 100
            for i in range(n+1):
                for j in range(n+1):
                    best = max(best, F(abs(fn(float(U0 + F(i, 2*n)), float(V0 + F(j, 2*n))))))
            best = F(float(best))
            heap = [(0, U0, U0 + F(1, 2), V0, V0 + F(1, 2))]
            upper = F(0); count = 0
            while heap:
                _, a0, a1, b0, b1 = heapq.heappop(heap)
                ub = rng(a0, a1, b0, b1)
                if ub <= best + TOL:
                    upper = max(upper, ub); continue
                am, bm = (a0+a1)/2, (b0+b1)/2
                best = max(best, F(abs(fn(float(am), float(bm)))))
                for x0, x1 in ((a0, am), (am, a1)):
                    for y0, y1 in ((b0, bm), (bm, b1)):
                        heapq.heappush(heap, (-float(ub), x0, x1, y0, y1))
                count += 1
                if count > 200000: print('too many boxes', q, name, flush=True); sys.exit(1)
            print(q, name, float(best), float(max(upper, best)), count, flush=True)


def far_quadrant():
    # Quadrant 11 in x = 1 - u, y = 1 - v (monomials in u, v near 1 cancel badly).
    x, y = sp.symbols('x y')
    TOL = F(2, 100)
    g = 9*u*(1-u)**2*v*(1-v)**2*(u-v)/(u+v)
    for name, d in (('uu', sp.diff(g, u, 2)), ('uv', sp.diff(g, u, v)), ('vv', sp.diff(g, v, 2))):
        num, den = sp.fraction(sp.factor(sp.together(d)))
        k = sp.degree(den, u)
        assert sp.expand(den - (u+v)**k) == 0
        N = sp.expand(num.subs({u: 1-x, v: 1-y}))
        P = sp.Poly(N, x, y)
        terms = [(m, F(int(sp.fraction(c)[0]), int(sp.fraction(c)[1]))) for m, c in zip(P.monoms(), P.coeffs())]
        fn = sp.lambdify((x, y), d.subs({u: 1-x, v: 1-y}))
        def rng(a0, a1, b0, b1):
            lo = hi = F(0)
            for (i, j), c in terms:
                pl, ph = a0**i * b0**j, a1**i * b1**j
                if c >= 0: lo += c*pl; hi += c*ph
                else: lo += c*ph; hi += c*pl
            dlo = (2 - a1 - b1)**k  # smallest denominator
            return max(abs(lo), abs(hi)) / dlo
        best = F(0)
        for i in range(101):
            for j in range(101):
                best = max(best, F(abs(fn(i/200, j/200))))
        heap = [(0, F(0), F(1, 2), F(0), F(1, 2))]
        upper = F(0); count = 0
        while heap:
            _, a0, a1, b0, b1 = heapq.heappop(heap)
            ub = rng(a0, a1, b0, b1)
            if ub <= best + TOL:
                upper = max(upper, ub); continue
            am, bm = (a0+a1)/2, (b0+b1)/2
            best = max(best, F(abs(fn(float(am), float(bm)))))
            for p0, p1 in ((a0, am), (am, a1)):
                for q0, q1 in ((b0, bm), (bm, b1)):
                    heapq.heappush(heap, (-float(ub), p0, p1, q0, q1))
            count += 1
            if count > 300000: print('too many boxes', name, flush=True); sys.exit(1)
        print('11 (x = 1 - u, y = 1 - v)', name, float(best), float(max(upper, best)), count, flush=True)

if len(sys.argv) > 1 and sys.argv[1] == '--quadrants':
    quadrants()
elif len(sys.argv) > 1 and sys.argv[1] == '--far-quadrant':
    far_quadrant()
else:
    run(quad_cases()[:2], True)
    run(tri_cases(), False)

