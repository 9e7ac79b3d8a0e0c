# The constants of techniques/common/curvature_bounds.h (kGregoryQuadBlend,
# kGregoryTriangleBlend): sup over the domain of |second derivatives| of the Gregory blend
# functions g_c = B_c(u, v) (a - b) / (a + b), by rigorous interval branch and bound in
# (r, s) = (a + b, a / (a + b)), where g's second derivatives are polynomials (asserted
# below). Prints per case: the best value found at a point, and the proven upper bound.
# Usage: python3 scripts/gregory_blend_constants.py [tolerance, default 1e-3]
# (sympy; several minutes; corners 2 and 3 of the quad only repeat corners 0 and 1).
import sympy as sp
from fractions import Fraction as F
import heapq, sys
TOL = float(sys.argv[1]) if len(sys.argv) > 1 else 1e-3
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
run(quad_cases()[:2], True)
run(tri_cases(), False)
