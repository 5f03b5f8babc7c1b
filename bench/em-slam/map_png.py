#!/usr/bin/env python3
"""A gv-em-slam run's map as a PNG (doc/benchmarks.md, "Doors on the real logs"): static vectors
blue, dynamic red, trajectory grey, doors (doors.txt) a green hinge and their two extreme leaf
states dashed; a 1 m bar at the bottom left. Pure Python (no imaging library).

usage: map_png.py RUN_DIR OUT.png [--px-per-m 20] [--centre X Y --half H] [--mark X Y]
  --centre/--half: a square window (map frame) instead of the whole map; --mark rings a point."""
import argparse, math, struct, zlib


def rows(path):
    return [l.split() for l in open(path) if l.strip() and not l.startswith('#')]


class Canvas:
    def __init__(self, x0, y0, x1, y1, scale):
        self.x0, self.y1, self.s = x0, y1, scale
        self.w, self.h = int((x1 - x0) * scale) + 1, int((y1 - y0) * scale) + 1
        self.px = bytearray(b'\xff' * (self.w * self.h * 3))

    def to_px(self, x, y):
        return (x - self.x0) * self.s, (self.y1 - y) * self.s

    def dot(self, x, y, colour, r):
        for i in range(int(x - r), int(x + r) + 1):
            for j in range(int(y - r), int(y + r) + 1):
                if 0 <= i < self.w and 0 <= j < self.h and (i - x) ** 2 + (j - y) ** 2 <= r * r + 0.5:
                    k = 3 * (j * self.w + i)
                    self.px[k:k + 3] = bytes(colour)

    def line(self, a, b, colour, r=1.0, dash=0):
        (x0, y0), (x1, y1) = self.to_px(*a), self.to_px(*b)
        n = int(max(abs(x1 - x0), abs(y1 - y0))) + 1
        for k in range(n + 1):
            if not (dash and (k // dash) % 2):
                self.dot(x0 + k / n * (x1 - x0), y0 + k / n * (y1 - y0), colour, r)

    def save(self, path):
        raw = b''.join(b'\x00' + bytes(self.px[3 * self.w * j:3 * self.w * (j + 1)]) for j in range(self.h))
        chunk = lambda t, b: struct.pack('>I', len(b)) + t + b + struct.pack('>I', zlib.crc32(t + b) & 0xffffffff)
        with open(path, 'wb') as f:
            f.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', self.w, self.h, 8, 2, 0, 0, 0))
                    + chunk(b'IDAT', zlib.compress(raw, 9)) + chunk(b'IEND', b''))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('run_dir')
    ap.add_argument('out')
    ap.add_argument('--px-per-m', type=float, default=20)
    ap.add_argument('--centre', type=float, nargs=2)
    ap.add_argument('--half', type=float, default=3)
    ap.add_argument('--mark', type=float, nargs=2)
    a = ap.parse_args()
    vectors = [(tuple(map(float, r[:2])), tuple(map(float, r[2:4])), r[5]) for r in rows(a.run_dir + '/vectors.txt')]
    poses = [tuple(map(float, r[1:3])) for r in rows(a.run_dir + '/trajectory.txt')]
    doors = [list(map(float, r[:6])) for r in rows(a.run_dir + '/doors.txt')]
    if a.centre:
        (cx, cy), h = a.centre, a.half
        box = (cx - h, cy - h, cx + h, cy + h)
    else:
        xs = [p[0] for v in vectors for p in v[:2]] + [p[0] for p in poses]
        ys = [p[1] for v in vectors for p in v[:2]] + [p[1] for p in poses]
        box = (min(xs) - 1, min(ys) - 1, max(xs) + 1, max(ys) + 1)
    inside = lambda p: box[0] - 2 <= p[0] <= box[2] + 2 and box[1] - 2 <= p[1] <= box[3] + 2
    c = Canvas(*box, a.px_per_m)
    for p, q in zip(poses, poses[1:]):
        if inside(p) and inside(q):
            c.line(p, q, (190, 190, 190), 0.5)
    width = max(1.0, a.px_per_m / 60)
    for p, q, state in vectors:
        if inside(p) or inside(q):
            c.line(p, q, (220, 0, 0) if state == 'dynamic' else (0, 0, 220), width)
    for hx, hy, length, a0, a1, _ in doors:
        if not inside((hx, hy)):
            continue
        for ang in (a0, a1):
            c.line((hx, hy), (hx + length * math.cos(ang), hy + length * math.sin(ang)), (0, 120, 0), width, dash=6)
        c.dot(*c.to_px(hx, hy), (0, 180, 0), max(3.0, 0.12 * a.px_per_m))
    if a.mark:
        mx, my = c.to_px(*a.mark)
        for k in range(400):
            t = 2 * math.pi * k / 400
            c.dot(mx + 0.3 * a.px_per_m * math.cos(t), my + 0.3 * a.px_per_m * math.sin(t), (220, 0, 220), 1)
    c.line((box[0] + 0.2, box[1] + 0.2), (box[0] + 1.2, box[1] + 0.2), (0, 0, 0), 1.5)
    c.save(a.out)


if __name__ == '__main__':
    main()
