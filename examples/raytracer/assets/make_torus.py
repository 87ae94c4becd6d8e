"""Writes torus.obj, the small mesh of the ray tracer's `lights` scene.

A torus around the y axis, major radius 0.75, minor radius 0.25, 24 x 8 segments
(384 triangles), with vertex normals; faces are counter-clockwise seen from outside.
Run: python3 make_torus.py > torus.obj
"""

import math

R, r, NU, NV = 0.75, 0.25, 24, 8


def vertex(i, j):
    u = 2 * math.pi * (i % NU) / NU
    v = 2 * math.pi * (j % NV) / NV
    n = (math.cos(v) * math.cos(u), math.sin(v), math.cos(v) * math.sin(u))
    c = (R * math.cos(u), 0.0, R * math.sin(u))
    return tuple(c[k] + r * n[k] for k in range(3)), n


def index(i, j):
    return (i % NU) * NV + (j % NV) + 1


def sub(a, b):
    return tuple(a[k] - b[k] for k in range(3))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def main():
    print("# torus: R = 0.75, r = 0.25, 24 x 8 segments, 384 triangles (make_torus.py)")
    for i in range(NU):
        for j in range(NV):
            print("v %.6f %.6f %.6f" % vertex(i, j)[0])
    for i in range(NU):
        for j in range(NV):
            print("vn %.6f %.6f %.6f" % vertex(i, j)[1])
    for i in range(NU):
        for j in range(NV):
            quad = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            p = [vertex(*q)[0] for q in quad]
            n = vertex(i, j)[1]
            face = cross(sub(p[1], p[0]), sub(p[2], p[0]))
            if sum(face[k] * n[k] for k in range(3)) < 0:
                quad.reverse()
            a, b, c, d = (index(*q) for q in quad)
            print("f %d//%d %d//%d %d//%d" % (a, a, b, b, c, c))
            print("f %d//%d %d//%d %d//%d" % (a, a, c, c, d, d))


main()
