#!/usr/bin/env python3
"""Writes the misconception classes of README.md: one class per kind, each a problem bank
and one submission per student (20 per slip, 20 right, 20 random per problem), and a
manifest saying which student holds which answer.

Every answer is computed here, with this file's own formulas (the textbook ones the README
cites); nothing is read from raygrade. Usage: make_classes.py OUT_DIR [--seed N].
"""

import argparse
import json
import math
import pathlib
import random
import shutil
import sys

PER_SLIP = 20
RIGHT = 20
RANDOM = 20


# --- vectors -------------------------------------------------------------------------

def add(a, b):
    return [x + y for x, y in zip(a, b)]


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def mul(a, s):
    return [x * s for x in a]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    return mul(a, 1 / norm(a))


def matvec(m, v):
    return [dot(row, v) for row in m]


def transpose(m):
    return [list(r) for r in zip(*m)]


def inverse3(m):
    a, b, c = m
    det = dot(a, cross(b, c))
    cols = [cross(b, c), cross(c, a), cross(a, b)]  # rows of the inverse's transpose
    return transpose([mul(r, 1 / det) for r in cols])


# --- intersect: sphere ---------------------------------------------------------------

SPHERE = {"O": [0, 0, 0], "D": [1, 2, 2], "C": [2, 6, 5], "r": 3}


def sphere_hits(p, slip=None):
    O, D, C, r = p["O"], p["D"], p["C"], p["r"]
    oc = sub(C, O) if slip == "oc-reversed" else sub(O, C)
    a = dot(D, D)
    b = 2 * dot(D, oc)
    c = dot(oc, oc) - (r if slip == "r-not-squared" else r * r)
    if slip == "a-taken-as-one":
        disc = b * b - 4 * c
        roots = [(-b - math.sqrt(disc)) / 2, (-b + math.sqrt(disc)) / 2]
    elif slip == "half-b-mixup":
        disc = b * b - a * c
        roots = [(-b - math.sqrt(disc)) / a, (-b + math.sqrt(disc)) / a]
    else:
        disc = b * b - 4 * a * c
        roots = [(-b - math.sqrt(disc)) / 2, (-b + math.sqrt(disc)) / 2]
        roots = [t * a if slip == "times-a" else t / a for t in roots]
    roots.sort()
    hits = []
    for t in roots:
        p = add(O, mul(D, t))
        hits.append({"t": t, "point": p, "normal": mul(sub(p, C), 1 / r)})
    return {"hits": hits}


# --- intersect: plane ----------------------------------------------------------------

PLANE = {"O": [1, 2, 3], "D": [1, -2, -1], "P0": [2, -3, 1], "n": [1, 2, 2]}


def plane_hits(p, slip=None):
    O, D, P0, n = p["O"], p["D"], p["P0"], p["n"]
    num = dot(sub(P0, O), n)
    if slip == "numerator-reversed":
        num = dot(sub(O, P0), n)
    elif slip == "origin-dropped":
        num = dot(P0, n)
    den = 1 if slip == "denominator-dropped" else dot(D, n)
    t = num / den
    return {"hits": [{"t": t, "point": add(O, mul(D, t)), "normal": unit(n)}]}


# --- intersect: triangle -------------------------------------------------------------

TRI = {"O": [2, 1, -1], "D": [0, 0, 2], "V": [[1, 0, 2], [5, 1, 2], [2, 4, 3]]}


def moller_trumbore(O, D, a, b, c):
    e1, e2 = sub(b, a), sub(c, a)
    p = cross(D, e2)
    det = dot(e1, p)
    s = sub(O, a)
    u = dot(s, p) / det
    q = cross(s, e1)
    v = dot(D, q) / det
    t = dot(e2, q) / det
    return t, u, v


def triangle_hits(p, slip=None):
    O, D = p["O"], p["D"]
    a, b, c = p["V"]
    t, u, v = moller_trumbore(O, D, a, b, c)
    assert 0 <= u and 0 <= v and u + v <= 1 and t > 0
    p = add(O, mul(D, t))
    n = unit(cross(sub(b, a), sub(c, a)))
    bary = [1 - u - v, u, v]
    if slip == "weights-rotated":
        bary = [u, v, 1 - u - v]
    elif slip == "normal-reversed":
        n = unit(cross(sub(c, a), sub(b, a)))
    elif slip == "t-along-unit":
        t = t * norm(D)
    return {"hits": [{"t": t, "point": p, "normal": n, "barycentric": bary}]}


# --- first hit -----------------------------------------------------------------------

FIRST = {"O": [0, 0, 0], "D": [1, 0, 0],
         "objects": [("sphere B", [8, 0.5, 0], 1.5), ("sphere C", [14, -1, 0], 2),
                     ("sphere A", [4, 1, 0], 1.5), ("sphere D", [-5, 0, 0], 2)]}


def sphere_roots(O, D, C, r):
    oc = sub(O, C)
    a, b, c = dot(D, D), 2 * dot(D, oc), dot(oc, oc) - r * r
    disc = b * b - 4 * a * c
    if disc < 0:
        return []
    return sorted([(-b - math.sqrt(disc)) / (2 * a), (-b + math.sqrt(disc)) / (2 * a)])


def first_hit(p, slip=None):
    O, D = p["O"], p["D"]
    cands = []  # (name, roots, centre, radius)
    for name, C, r in p["objects"]:
        cands.append((name, sphere_roots(O, D, C, r), C, r))
    ahead = [(n, [t for t in rs if t > 0], C, r) for n, rs, C, r in cands]
    ahead = [x for x in ahead if x[1]]
    if slip == "behind-origin":
        name, t, C, r = min(((n, t, C, r) for n, rs, C, r in cands for t in rs),
                            key=lambda x: x[1])
    elif slip == "largest-t":
        name, rs, C, r = max(ahead, key=lambda x: x[1][0])
        t = rs[0]
    elif slip == "first-listed":
        name, rs, C, r = ahead[0]
        t = rs[0]
    else:
        name, rs, C, r = min(ahead, key=lambda x: x[1][0])
        t = rs[-1] if slip == "far-root" else rs[0]
    p = add(O, mul(D, t))
    return {"object": name, "hits": [{"t": t, "point": p, "normal": mul(sub(p, C), 1 / r)}]}


# --- camera ray (focal length) -------------------------------------------------------

CAM = {"eye": [1, 0, 2], "d": [0, 0, -1], "up": [0, 1, 0], "f": 3, "res": [8, 6],
       "pixel": [6, 1]}


def camera_ray(p, slip=None):
    d, up, f = p["d"], p["up"], p["f"]
    resx, resy = p["res"]
    x, y = p["pixel"]
    half = 0 if slip == "no-half-pixel" else 0.5
    if slip == "y-flipped":
        y = resy - 1 - y
    xd = x + half - resx / 2
    yd = y + half - resy / 2
    right = cross(up, d) if slip == "right-reversed" else cross(d, up)
    ff = 1 if slip == "focal-dropped" else f
    dr = add(add(mul(d, ff), mul(right, xd)), mul(up, yd))
    return {"ray": {"origin": p["eye"], "direction": dr}}


# --- view ray (look-at camera, field of view) ----------------------------------------

VIEW = {"eye": [1, 2, 3], "target": [1, 2, 0], "up": [0, 1, 0], "fov": 70, "res": [10, 6],
        "pixel": [7, 1]}


def view_ray(p, slip=None):
    e = p["eye"]
    view = sub(p["target"], e)
    w = mul(unit(view), -1)
    u = unit(cross(p["up"], w))
    v = cross(w, u)
    nx, ny = p["res"]
    i, j = p["pixel"]
    fov = p["fov"]
    if slip == "full-fov":
        half_w = math.tan(math.radians(fov))
    elif slip == "fov-degrees":
        half_w = math.tan(fov / 2)
    else:
        half_w = math.tan(math.radians(fov / 2))
    half_h = half_w if slip == "aspect-ignored" else half_w * ny / nx
    left, right, bottom, top = -half_w, half_w, -half_h, half_h
    s = 0 if slip == "no-half-pixel" else 0.5
    us = left + (right - left) * (i + s) / nx
    if slip == "rows-from-bottom":
        vs = bottom + (top - bottom) * (j + s) / ny
    else:
        vs = top - (top - bottom) * (j + s) / ny
    direction = add(add(mul(w, -1), mul(u, us)), mul(v, vs))
    return {"origin": e, "direction": direction}


# --- reflect -------------------------------------------------------------------------

REFL = {"d": [2, -3, 1], "n": [1, 2, 0]}


def reflect(p, slip=None):
    d, n = p["d"], p["n"]
    nh = n if slip == "normal-not-unit" else unit(n)
    k = dot(d, nh)
    if slip == "plus-sign":
        r = add(d, mul(nh, 2 * k))
    elif slip == "no-two":
        r = sub(d, mul(nh, k))
    elif slip == "light-form":
        r = sub(mul(nh, 2 * k), d)
    else:
        r = sub(d, mul(nh, 2 * k))
    return {"direction": r, "unit_direction": unit(r)}


# --- refract -------------------------------------------------------------------------

REFR = {"d": [1, -1.2, 0], "n": [0, 1, 0], "n1": 1, "n2": 1.5}


def refract(p, slip=None):
    d, n = unit(p["d"]), unit(p["n"])
    n1, n2 = p["n1"], p["n2"]
    if dot(d, n) > 0:
        n = mul(n, -1)
    cos_i = -dot(d, n)
    theta_i = math.degrees(math.acos(cos_i))
    tangent = unit(add(d, mul(n, cos_i)))  # the along-surface side the ray travels
    eta = n2 / n1 if slip == "n1-n2-swapped" else n1 / n2
    if slip == "angle-from-surface":
        theta_i = 90 - theta_i
    if slip == "degrees-as-radians":
        sin_t = eta * math.sin(theta_i)
    else:
        sin_t = eta * math.sin(math.radians(theta_i))
    if slip == "angles-proportional":
        theta_t = eta * theta_i
    else:
        theta_t = math.degrees(math.asin(sin_t))
    tt = math.radians(theta_t)
    direction = sub(mul(tangent, math.sin(tt)), mul(n, math.cos(tt)))
    return {"total_internal_reflection": False, "direction": direction,
            "angle_of_incidence": theta_i, "angle_of_refraction": theta_t}


# --- shade (Phong) -------------------------------------------------------------------

SHADE = {"P": [0, 0, 0], "N": [0, 1, 0], "eye": [-3, 4, 0], "Ia": 2, "ka": 0.1, "kd": 0.6,
         "ks": 0.3, "n": 12,
         "lights": [("A", [0.5, 1, 0.25], False), ("B", [0, 9, 0], True),
                    ("C", [5, -1, 0], False)]}


def shade(p, slip=None):
    s = p
    P, N = s["P"], s["N"]
    V = unit(sub(s["eye"], P))
    ambient = s["ka"] * s["Ia"]
    diffuse = specular = 0.0
    lights = []
    for name, pos, blocked in s["lights"]:
        L = sub(pos, P)
        if slip != "light-not-unit":
            L = unit(L)
        ndl = dot(N, L)
        R = sub(L, mul(N, 2 * ndl)) if slip == "reflect-sign" else sub(mul(N, 2 * ndl), L)
        if slip == "halfway-vector":
            rdv = dot(N, unit(add(unit(L), V)))
        else:
            rdv = dot(R, V)
        counted = not blocked or slip == "blocked-light-counted"
        reaches = counted and (ndl > 0 or slip == "no-clamp")
        d = sp = 0.0
        if reaches:
            d = s["kd"] * (ndl if slip == "no-clamp" else max(0.0, ndl))
            rv = max(0.0, rdv)
            sp = s["ks"] * (rv if slip == "exponent-forgotten" else rv ** s["n"])
            diffuse += d
            specular += sp
        lights.append({"light": name, "reaches": reaches, "n_dot_l": ndl, "r_dot_v": rdv,
                       "diffuse": d, "specular": sp})
    return {"ambient": ambient, "diffuse": diffuse, "specular": specular,
            "intensity": ambient + diffuse + specular, "lights": lights}


# --- normal at a point ---------------------------------------------------------------

NSPH = {"C": [1, 2, -1], "r": 3, "P": [3, 1, 1]}
NSHEAR = {"M": [[2, 1, 0], [0, 1, 0], [0, 0, 1]], "p_obj": [0.6, 0.8, 0]}


def normal_sphere(p, slip=None):
    C, P = p["C"], p["P"]
    if slip == "inward":
        return {"normal": unit(sub(C, P))}
    if slip == "point-as-normal":
        return {"normal": unit(P)}
    return {"normal": unit(sub(P, C))}


def normal_sheared(p, slip=None):
    M, n_obj = p["M"], p["p_obj"]  # unit sphere at the origin: n' = p'
    if slip == "by-M":
        n = matvec(M, n_obj)
    elif slip == "inverse-not-transposed":
        n = matvec(inverse3(M), n_obj)
    elif slip == "object-space":
        n = n_obj
    else:
        n = matvec(transpose(inverse3(M)), n_obj)
    return {"normal": unit(n), "object_normal": n_obj}


# --- interpolate ---------------------------------------------------------------------

INTERP = {"V": [[1, 0, 0], [5, 1, 0], [2, 4, 0]],
          "N": [[0, 0, 1], [0.6, 0, 0.8], [0, 0.6, 0.8]],
          "T": [[0.1, 0.2], [0.9, 0.3], [0.4, 0.8]], "w": [0.5, 0.3, 0.2]}


def interpolate(p, slip=None):
    V, Ns, T = p["V"], p["N"], p["T"]
    P = [sum(w * v[k] for w, v in zip(p["w"], V)) for k in range(3)]
    a, b, c = V
    area = norm(cross(sub(b, a), sub(c, a))) / 2
    # weights from sub-triangle areas (the point lies in the triangle)
    wa = norm(cross(sub(b, P), sub(c, P))) / 2
    wb = norm(cross(sub(c, P), sub(a, P))) / 2
    wc = norm(cross(sub(a, P), sub(b, P))) / 2
    w = [wa / area, wb / area, wc / area]
    if slip == "weights-rotated":
        w = [w[1], w[2], w[0]]
    elif slip == "areas-not-divided":
        w = [wa, wb, wc]
    n = [sum(wi * ni[k] for wi, ni in zip(w, Ns)) for k in range(3)]
    u = sum(wi * ti[0] for wi, ti in zip(w, T))
    v = sum(wi * ti[1] for wi, ti in zip(w, T))
    if slip == "texcoord-swapped":
        u, v = v, u
    elif slip == "v-flipped":
        v = 1 - v
    return {"barycentric": w, "normal": unit(n), "u": u, "v": v}


# --- Fresnel -------------------------------------------------------------------------

SCHLICK = {"n1": 1.5, "n2": 1, "angle": 30}
EXACT = {"n1": 1, "n2": 1.5, "angle": 30}


def fresnel_schlick(p, slip=None):
    n1, n2, th = p["n1"], p["n2"], math.radians(p["angle"])
    sin_t = n1 / n2 * math.sin(th)
    theta_t = math.asin(sin_t)
    r0 = (n1 - n2) / (n1 + n2)
    if slip != "r0-not-squared":
        r0 = r0 * r0
    if slip == "schlick-cos-i":
        cos = math.cos(th)
    elif slip == "schlick-degrees":
        cos = math.cos(math.degrees(theta_t))
    else:
        cos = math.cos(theta_t) if n1 > n2 else math.cos(th)
    f = r0 + (1 - r0) * (1 - cos) ** 5
    return {"reflectance": f, "transmittance": 1 - f, "r0": r0}


def fresnel_exact(p, slip=None):
    n1, n2, th = p["n1"], p["n2"], math.radians(p["angle"])
    if slip == "n1-n2-swapped":
        n1, n2 = n2, n1
    ci = math.cos(th)
    ct = math.sqrt(1 - (n1 / n2) ** 2 * (1 - ci * ci))
    rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct)
    rp = (n1 * ct - n2 * ci) / (n1 * ct + n2 * ci)
    if slip != "not-squared":
        rs, rp = rs * rs, rp * rp
    f = rs if slip == "rs-only" else (rs + rp) / 2
    return {"reflectance": f, "transmittance": 1 - f, "r_s": rs, "r_p": rp}


# --- the problems --------------------------------------------------------------------

SRC = "tests/data/misconceptions (issue 48)"

# A second set of numbers for each problem, so that no slip is judged on one problem alone.
SPHERE2 = {"O": [1, -1, 2], "D": [0, 3, 4], "C": [2, 5, 9], "r": 2.5}
PLANE2 = {"O": [0, 1, -2], "D": [2, 1, -3], "P0": [1, 4, 1], "n": [0, 3, -1]}
TRI2 = {"O": [1, 1, 6], "D": [0.5, 0.5, -3], "V": [[0, 0, 0], [4, 0, 1], [0, 5, 0]]}
FIRST2 = {"O": [1, 2, 0], "D": [0, 2, 0],
          "objects": [("ball 3", [1.5, 20, 0], 2), ("ball 1", [1, 30, 0.5], 3),
                      ("ball 2", [0.5, 12, 0], 1.5), ("ball 4", [1, -6, 0], 1)]}
CAM2 = {"eye": [0, 1, 0], "d": [1, 0, 0], "up": [0, 0, 1], "f": 2, "res": [6, 4],
        "pixel": [1, 3]}
VIEW2 = {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov": 50, "res": [12, 8],
         "pixel": [2, 6]}
REFL2 = {"d": [-1, -2, 3], "n": [1, 1, -2]}
REFR2 = {"d": [0.7, -1, 0.2], "n": [0, 1, 0], "n1": 1, "n2": 1.33}
SHADE2 = {"P": [0, 0, 0], "N": [0, 0, 1], "eye": [0, 3, 4], "Ia": 1, "ka": 0.2, "kd": 0.5,
          "ks": 0.4, "n": 8,
          "lights": [("key", [0.3, -0.6, 0.9], False), ("top", [0, 0, 5], True),
                     ("low", [2, 0, -1], False)]}
NSPH2 = {"C": [-1, 0, 2], "r": 5, "P": [2, 4, 2]}
NSHEAR2 = {"M": [[1, 0, 0], [1, 2, 0], [0, 0, 1]], "p_obj": [0.6, 0.8, 0]}
SCHLICK2 = {"n1": 1.33, "n2": 1, "angle": 40}
EXACT2 = {"n1": 1, "n2": 1.33, "angle": 45}
INTERP2 = {"V": [[0, 0, 1], [3, 0, 0], [0, 6, 0]],
           "N": [[0.8, 0, 0.6], [0, 0, 1], [0, 0.6, 0.8]],
           "T": [[0, 0], [1, 0.2], [0.3, 0.9]], "w": [0.25, 0.35, 0.4]}


def spec_sphere(p):
    return {"title": "A ray meets a sphere (the direction is not a unit vector)",
            "ray": {"origin": p["O"], "direction": p["D"]},
            "object": {"type": "sphere", "center": p["C"], "radius": p["r"]},
            "points": {"t": 2, "point": 1, "normal": 1}}


def spec_plane(p):
    return {"title": "A ray meets a plane given by a point and a normal",
            "ray": {"origin": p["O"], "direction": p["D"]},
            "object": {"type": "plane", "point": p["P0"], "normal": p["n"]},
            "points": {"t": 2, "point": 1, "normal": 1}}


def spec_triangle(p):
    return {"title": "A ray through a triangle, with barycentric weights",
            "ray": {"origin": p["O"], "direction": p["D"]},
            "object": {"type": "triangle", "vertices": p["V"]},
            "points": {"t": 2, "point": 1, "normal": 1, "barycentric": 1}}


def spec_first_hit(p):
    return {"kind": "first-hit", "title": "Which of four spheres is hit first?",
            "ray": {"origin": p["O"], "direction": p["D"]},
            "objects": [{"name": n, "type": "sphere", "center": C, "radius": r}
                        for n, C, r in p["objects"]],
            "points": {"object": 2, "t": 1, "point": 1, "normal": 1}}


def spec_camera(p):
    return {"kind": "camera-ray", "title": "The ray through a pixel's centre",
            "camera": {"eye": p["eye"], "direction": p["d"], "up": p["up"],
                       "focal_length": p["f"], "resolution": p["res"]},
            "pixel": p["pixel"], "convention": "center"}


def spec_view(p):
    return {"kind": "view-ray", "title": "A look-at camera with a horizontal field of view",
            "camera": {"projection": "perspective", "eye": p["eye"], "target": p["target"],
                       "up": p["up"], "fov": p["fov"], "fov_axis": "horizontal",
                       "resolution": p["res"], "pixel_origin": "top-left"},
            "pixel": p["pixel"], "convention": "center"}


def spec_reflect(p):
    return {"kind": "reflect", "title": "Reflect a ray (the normal is not unit)",
            "direction": p["d"], "normal": p["n"],
            "points": {"direction": 1, "unit_direction": 1}}


def spec_refract(p):
    return {"kind": "refract", "title": "From air into a denser medium",
            "direction": p["d"], "normal": p["n"], "n1": p["n1"], "n2": p["n2"],
            "points": {"direction": 1, "total_internal_reflection": 1, "angle_of_incidence": 1,
                       "angle_of_refraction": 1}}


def spec_shade(p):
    return {"kind": "shade",
            "title": "Phong shading: a visible light, a blocked one, one below the horizon",
            "point": p["P"], "normal": p["N"], "eye": p["eye"], "ambient_light": p["Ia"],
            "material": {"ambient": p["ka"], "diffuse": p["kd"], "specular": p["ks"],
                         "shininess": p["n"]},
            "lights": [dict({"name": n, "position": q}, **({"blocked": True} if b else {}))
                       for n, q, b in p["lights"]],
            "points": {"intensity": 1, "ambient": 1, "diffuse": 1, "specular": 1, "lights": 1}}


def spec_normal_sphere(p):
    return {"kind": "normal", "title": "The normal of a sphere",
            "object": {"type": "sphere", "center": p["C"], "radius": p["r"]}, "point": p["P"]}


def spec_normal_sheared(p):
    return {"kind": "normal", "title": "The normal of a sheared sphere",
            "object": {"type": "sphere", "center": [0, 0, 0], "radius": 1,
                       "transform": [{"matrix": p["M"]}]},
            "point": matvec(p["M"], p["p_obj"])}


def spec_interpolate(p):
    return {"kind": "interpolate", "title": "The smooth normal and texture coordinate at a point",
            "vertices": p["V"], "normals": p["N"], "texcoords": p["T"],
            "point": [sum(w * v[k] for w, v in zip(p["w"], p["V"])) for k in range(3)],
            "points": {"normal": 2, "barycentric": 1, "u": 1, "v": 1}}


def spec_schlick(p):
    return {"kind": "fresnel", "model": "schlick",
            "title": "Schlick's approximation leaving a denser medium",
            "n1": p["n1"], "n2": p["n2"], "angle": p["angle"],
            "points": {"reflectance": 1, "transmittance": 1, "r0": 1}}


def spec_exact(p):
    return {"kind": "fresnel", "model": "exact",
            "title": "The Fresnel equations into a denser medium",
            "n1": p["n1"], "n2": p["n2"], "angle": p["angle"],
            "points": {"reflectance": 1, "transmittance": 1, "r_s": 1, "r_p": 1}}


# kind -> [(problem id, its statement, the answer function, its numbers, slip group, slips)]
PROBLEMS = {
    "intersect": [
        ("mc-sphere", spec_sphere, sphere_hits, [SPHERE, SPHERE2], "sphere",
         ["a-taken-as-one", "half-b-mixup", "times-a", "oc-reversed", "r-not-squared"]),
        ("mc-plane", spec_plane, plane_hits, [PLANE, PLANE2], "plane",
         ["numerator-reversed", "origin-dropped", "denominator-dropped"]),
        ("mc-triangle", spec_triangle, triangle_hits, [TRI, TRI2], "triangle",
         ["weights-rotated", "normal-reversed", "t-along-unit"]),
    ],
    "first-hit": [
        ("mc-first-hit", spec_first_hit, first_hit, [FIRST, FIRST2], "first-hit",
         ["far-root", "behind-origin", "largest-t", "first-listed"]),
    ],
    "camera-ray": [
        ("mc-camera-ray", spec_camera, camera_ray, [CAM, CAM2], "camera-ray",
         ["no-half-pixel", "y-flipped", "right-reversed", "focal-dropped"]),
    ],
    "view-ray": [
        ("mc-view-ray", spec_view, view_ray, [VIEW, VIEW2], "view-ray",
         ["full-fov", "fov-degrees", "aspect-ignored", "rows-from-bottom", "no-half-pixel"]),
    ],
    "reflect": [
        ("mc-reflect", spec_reflect, reflect, [REFL, REFL2], "reflect",
         ["plus-sign", "no-two", "light-form", "normal-not-unit"]),
    ],
    "refract": [
        ("mc-refract", spec_refract, refract, [REFR, REFR2], "refract",
         ["n1-n2-swapped", "angle-from-surface", "degrees-as-radians", "angles-proportional"]),
    ],
    "shade": [
        ("mc-shade", spec_shade, shade, [SHADE, SHADE2], "shade",
         ["exponent-forgotten", "reflect-sign", "no-clamp", "light-not-unit",
          "blocked-light-counted", "halfway-vector"]),
    ],
    "normal": [
        ("mc-normal-sphere", spec_normal_sphere, normal_sphere, [NSPH, NSPH2], "normal",
         ["inward", "point-as-normal"]),
        ("mc-normal-sheared", spec_normal_sheared, normal_sheared, [NSHEAR, NSHEAR2], "normal",
         ["by-M", "inverse-not-transposed", "object-space"]),
    ],
    "interpolate": [
        ("mc-interpolate", spec_interpolate, interpolate, [INTERP, INTERP2], "interpolate",
         ["weights-rotated", "areas-not-divided", "texcoord-swapped", "v-flipped"]),
    ],
    "fresnel": [
        ("mc-fresnel-schlick", spec_schlick, fresnel_schlick, [SCHLICK, SCHLICK2], "fresnel",
         ["schlick-cos-i", "r0-not-squared", "schlick-degrees"]),
        ("mc-fresnel-exact", spec_exact, fresnel_exact, [EXACT, EXACT2], "fresnel",
         ["rs-only", "not-squared", "n1-n2-swapped"]),
    ],
}


# --- random answers ------------------------------------------------------------------

def randomise(value, rng, key=""):
    """A plausible random answer of the same shape: each number drawn in a range of its
    quantity around the right value (a t in [0, 2t], a unit vector's components in [-1, 1],
    an angle in [0, 90], a share in [0, 1], any other number within max(1, |x|) of x)."""
    if isinstance(value, bool) or isinstance(value, str) or value is None:
        return value
    if isinstance(value, dict):
        return {k: randomise(v, rng, k) for k, v in value.items()}
    if isinstance(value, list):
        if key in ("normal", "unit_direction", "object_normal") or (
                key == "direction" and all(abs(x) <= 1 for x in value)):
            return [rng.uniform(-1, 1) for _ in value]
        return [randomise(v, rng, key) for v in value]
    x = float(value)
    if key == "t":
        return rng.uniform(0, 2 * abs(x) if x else 1)
    if key.startswith("angle"):
        return rng.uniform(0, 90)
    if key in ("reflectance", "transmittance", "r0", "r_s", "r_p", "barycentric", "u", "v"):
        return rng.uniform(0, 1)
    spread = max(1.0, abs(x))
    return rng.uniform(x - spread, x + spread)


# --- checks --------------------------------------------------------------------------

def numbers(value):
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return []
    if isinstance(value, (int, float)):
        return [float(value)]
    if isinstance(value, dict):
        return [x for k in sorted(value) for x in numbers(value[k])]
    return [x for v in value for x in numbers(v)]


def differ(a, b, rtol=0.01):
    """True when two answers differ by more than 1% relative in some number (ten times
    the default tolerance of 0.1%), or in shape, a label or a verdict."""
    if json.dumps(strip(a), sort_keys=True) != json.dumps(strip(b), sort_keys=True):
        return True
    na, nb = numbers(a), numbers(b)
    if len(na) != len(nb):
        return True
    return any(abs(x - y) > rtol * max(abs(x), abs(y), 1e-3) for x, y in zip(na, nb))


def strip(value):
    """The answer's non-numbers (labels, verdicts, shape), numbers replaced by 0."""
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if isinstance(value, (int, float)):
        return 0
    if isinstance(value, dict):
        return {k: strip(v) for k, v in value.items()}
    return [strip(v) for v in value]


def rounded(value, digits=6):
    """Numbers as a student copies them from a calculator: six significant digits."""
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if isinstance(value, (int, float)):
        return float(f"{value:.{digits}g}")
    if isinstance(value, dict):
        return {k: rounded(v, digits) for k, v in value.items()}
    return [rounded(v, digits) for v in value]


def as_unit_directions(answer):
    """The same answer with every direction vector given as a unit vector (graded as
    directions, so any positive multiple is the same answer)."""
    out = json.loads(json.dumps(answer))
    if "ray" in out:
        out["ray"]["direction"] = unit(out["ray"]["direction"])
    elif "direction" in out and "origin" in out:
        out["direction"] = unit(out["direction"])
    return out


# --- writing -------------------------------------------------------------------------

def plant(kind, pid, fn, params, group, slips, write, rng):
    """Writes one problem's students: PER_SLIP per slip, RIGHT right, RANDOM random.
    Returns the faults found: a slip that gives the right answer or another slip's."""
    faults = []
    right = fn(params)
    answers = {s: fn(params, s) for s in slips}
    for s, a in answers.items():
        if not differ(a, right):
            faults.append(f"{pid}: slip {s} gives the right answer")
        for s2, a2 in answers.items():
            if s < s2 and not differ(a, a2):
                faults.append(f"{pid}: slips {s} and {s2} give the same answer")
    # half the students of the camera kinds give the ray's direction as a unit vector
    unit_dirs = kind in ("camera-ray", "view-ray")
    for s, a in answers.items():
        for j in range(PER_SLIP):
            write(pid, as_unit_directions(a) if unit_dirs and j % 2 else a,
                  {"role": "slip", "slip": f"{group}/{s}"})
    for j in range(RIGHT):
        write(pid, as_unit_directions(right) if unit_dirs and j % 2 else right,
              {"role": "right"})
    for j in range(RANDOM):
        write(pid, randomise(right, rng), {"role": "random"})
    return faults


def build(out, seed):
    rng = random.Random(seed)
    out = pathlib.Path(out)
    manifest = {"seed": seed, "kinds": {}}
    faults = []
    for kind, problems in PROBLEMS.items():
        kdir = out / kind
        shutil.rmtree(kdir, ignore_errors=True)  # no student left from an earlier run
        (kdir / "submissions").mkdir(parents=True, exist_ok=True)
        bank = {"title": f"Misconception class: {kind}", "problems": []}
        pending = []

        def write(pid, answer, role):
            pending.append((pid, answer, role))

        for base, spec, fn, variants, group, slips in problems:
            for k, params in enumerate(variants):
                pid = f"{base}-{k + 1}"
                bank["problems"].append(dict({"id": pid}, **spec(params), source=SRC))
                faults += plant(kind, pid, fn, params, group, slips, write, rng)
        # a class in no particular order: slips, right and random answers mixed
        rng.shuffle(pending)
        students = {}
        for number, (pid, answer, role) in enumerate(pending, start=1):
            sid = f"{kind}-s{number:04d}"
            sub_ = {"student": {"name": f"Student {number}", "id": sid},
                    "answers": {pid: rounded(answer)}}
            (kdir / "submissions" / f"{sid}.json").write_text(json.dumps(sub_) + "\n")
            students[sid] = dict(role, problem=pid)
        (kdir / "problems.json").write_text(json.dumps(bank, indent=1) + "\n")
        manifest["kinds"][kind] = {"students": students}
    (out / "manifest.json").write_text(json.dumps(manifest, indent=1) + "\n")
    return faults


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--seed", type=int, default=48)
    args = ap.parse_args()
    faults = build(args.out, args.seed)
    for f in faults:
        print(f"make_classes: {f}", file=sys.stderr)
    return 1 if faults else 0


if __name__ == "__main__":
    sys.exit(main())
