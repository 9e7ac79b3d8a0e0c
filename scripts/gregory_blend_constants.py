# The constants of techniques/common/curvature_bounds.h (kGregoryQuadBlend,
# kGregoryTriangleBlend): sup over the domain of |second derivatives| of the Gregory blend
# functions g_c = B_c(u, v) (a - b) / (a + b), by rigorous interval branch and bound in
# (r, s) = (a + b, a / (a + b)), where g's second derivatives are polynomials (asserted
# below). Prints per case: the best value found at a point, and the proven upper bound.
# The derivation and the constants it proved: docs/derivations/gregory_blend_constants.md.
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

# The triangle's regions: the domain cut at the edges' midpoints into the three corner
# triangles (u, v or w at least 1/2) and the middle one, as (u, v) vertices.
TRI_REGIONS = {
    'u': ((F(1), F(0)), (F(1, 2), F(0)), (F(1, 2), F(1, 2))),
    'v': ((F(0), F(1)), (F(0), F(1, 2)), (F(1, 2), F(1, 2))),
    'w': ((F(0), F(0)), (F(1, 2), F(0)), (F(0), F(1, 2))),
    'mid': ((F(1, 2), F(0)), (F(1, 2), F(1, 2)), (F(0), F(1, 2))),
}

def bernstein_max(poly, tri):
    """max |Bernstein coefficient| of the polynomial `poly` in (u, v) on the triangle `tri`:
    an upper bound of |poly| there (the Bernstein weights are >= 0 and sum to 1)."""
    l1, l2 = sp.symbols('l1 l2')
    (x0, y0), (x1, y1), (x2, y2) = tri
    l0 = 1 - l1 - l2
    sub = {u: x0*l0 + x1*l1 + x2*l2, v: y0*l0 + y1*l1 + y2*l2}
    P = sp.Poly(sp.expand(poly.subs(sub, simultaneous=True)), l1, l2)
    m = P.total_degree()
    # Homogenise with l0: coefficient of l0^(m-i-j) l1^i l2^j from each monomial l1^a l2^b
    # (l0 + l1 + l2)^(m-a-b) = ((1 - l1 - l2) + l1 + l2)^(m-a-b) in the barycentric basis.
    coef = {}
    for (a, b), c in zip(P.monoms(), P.coeffs()):
        c = F(int(sp.fraction(c)[0]), int(sp.fraction(c)[1]))
        rest = m - a - b
        # (l0 + l1 + l2)^rest = sum rest! / (p! q! t!) l0^p l1^q l2^t
        from math import factorial
        for q in range(rest + 1):
            for t in range(rest + 1 - q):
                pp = rest - q - t
                mult = F(factorial(rest), factorial(pp) * factorial(q) * factorial(t))
                key = (pp, a + q, b + t)
                coef[key] = coef.get(key, F(0)) + c * mult
    from math import factorial
    best = F(0)
    for (i, j, k), c in coef.items():
        binom = F(factorial(m), factorial(i) * factorial(j) * factorial(k))
        best = max(best, abs(c / binom))
    return best

def split(tri):
    a, b, c = tri
    mid = lambda p, q: ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2)
    ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
    return [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]

def region_bound(num, base, k, tri, depth):
    """sup |num / base^k| over the triangle `tri` (base linear and > 0 there): the largest
    over its 4^depth sub-triangles of max |Bernstein coefficient of num| / min(base)^k (base
    is smallest at a vertex)."""
    pieces = [tri]
    for _ in range(depth):
        pieces = [q for p in pieces for q in split(p)]
    fb = sp.lambdify((u, v), base)
    upper = F(0)
    for p in pieces:
        dmin = min(F(sp.Rational(base.subs({u: sp.Rational(x.numerator, x.denominator),
                                            v: sp.Rational(y.numerator, y.denominator)})).p,
                     sp.Rational(base.subs({u: sp.Rational(x.numerator, x.denominator),
                                            v: sp.Rational(y.numerator, y.denominator)})).q)
                   for x, y in p)
        assert dmin > 0
        upper = max(upper, bernstein_max(num, p) / dmin**k)
    return upper

def quad_far_quadrant(depth):
    """The quad's g_0 on [1/2, 1]^2 (u + v >= 1 there), as two triangles."""
    g = 9*u*(1-u)**2*v*(1-v)**2*(u-v)/(u+v)
    h = F(1, 2)
    tris = (((h, h), (F(1), h), (F(1), F(1))), ((h, h), (F(1), F(1)), (h, F(1))))
    for name, d in (('uu', sp.diff(g, u, 2)), ('uv', sp.diff(g, u, v)), ('vv', sp.diff(g, v, 2))):
        num, den = sp.fraction(sp.factor(sp.together(d)))
        base = u + v
        k = sp.Poly(den, u, v).total_degree()
        scale = sp.cancel(den / base**k)
        assert scale.free_symbols == set(), den
        num = sp.expand(num / scale)
        upper = max(region_bound(num, base, k, t, depth) for t in tris)
        fn = sp.lambdify((u, v), d)
        sampled = max(abs(fn(0.5 + i / 120, 0.5 + j / 120)) for i in range(61) for j in range(61))
        print('quad 0 quadrant 11', name, 'sampled %.4f' % sampled, 'bound %.4f' % float(upper),
              flush=True)

def triangle_regions(depth):
    """Per blend g_c (b211, b121, b112) and region away from its corner: sup |second
    derivative| over the region, bounded by the Bernstein coefficients of the numerator over
    the smallest denominator on each of 4^depth sub-triangles (exact rationals); with the
    largest value sampled on a grid of the region beside it."""
    w = 1 - u - v
    own = ['u', 'v', 'w']
    for c, (basis, a, b) in enumerate(tri_cases()):
        g = basis*(a - b)/(a + b)
        for name, d in (('uu', sp.diff(g, u, 2)), ('uv', sp.diff(g, u, v)), ('vv', sp.diff(g, v, 2))):
            num, den = sp.fraction(sp.factor(sp.together(d)))
            base = sp.expand(a + b)
            k = sp.Poly(den, u, v).total_degree()
            scale = sp.cancel(den / base**k)  # den is a constant times (a + b)^k
            assert scale.free_symbols == set(), den
            num = sp.expand(num / scale)
            fn = sp.lambdify((u, v), d)
            for region, tri in TRI_REGIONS.items():
                if region == own[c]: continue
                upper = region_bound(num, base, k, tri, depth)
                sampled = 0.0
                n = 60
                (x0, y0), (x1, y1), (x2, y2) = [(float(x), float(y)) for x, y in tri]
                for i in range(n + 1):
                    for j in range(n + 1 - i):
                        l1, l2 = i / n, j / n
                        l0 = 1 - l1 - l2
                        uu_, vv_ = x0*l0 + x1*l1 + x2*l2, y0*l0 + y1*l1 + y2*l2
                        sampled = max(sampled, abs(fn(uu_, vv_)))
                print('tri', c, region, name, 'sampled %.4f' % sampled, 'bound %.4f' % float(upper),
                      flush=True)

if len(sys.argv) > 1 and sys.argv[1] == '--triangle-regions':
    triangle_regions(int(sys.argv[2]) if len(sys.argv) > 2 else 3)
elif len(sys.argv) > 1 and sys.argv[1] == '--far-quadrant-bernstein':
    quad_far_quadrant(int(sys.argv[2]) if len(sys.argv) > 2 else 3)
elif len(sys.argv) > 1 and sys.argv[1] == '--quadrants':
    quadrants()
elif len(sys.argv) > 1 and sys.argv[1] == '--far-quadrant':
    far_quadrant()
else:
    run(quad_cases()[:2], True)
    run(tri_cases(), False)

