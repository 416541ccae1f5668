# Writes the two cross PNGs of the EnvironmentLight render cases (sRGB-encoded 8-bit).
import math, struct, zlib, sys

FACES = {  # name: (axis, right, up, (column, row) in a horizontal cross)
    "front": ((0, 0, -1), (1, 0, 0), (0, 1, 0), (1, 1)),
    "back": ((0, 0, 1), (-1, 0, 0), (0, 1, 0), (3, 1)),
    "left": ((-1, 0, 0), (0, 0, -1), (0, 1, 0), (0, 1)),
    "right": ((1, 0, 0), (0, 0, 1), (0, 1, 0), (2, 1)),
    "top": ((0, 1, 0), (1, 0, 0), (0, 0, 1), (1, 0)),
    "bottom": ((0, -1, 0), (1, 0, 0), (0, 0, -1), (1, 2)),
}

def encode(c):
    c = min(max(c, 0.0), 1.0)
    v = c * 12.92 if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055
    return round(v * 255)

def cross(side, radiance):
    w, h = 4 * side, 3 * side
    rows = [[(0, 0, 0)] * w for _ in range(h)]
    for axis, right, up, (cx, cy) in FACES.values():
        for y in range(side):
            for x in range(side):
                u = (2 * x + 1) / side - 1
                v = 1 - (2 * y + 1) / side
                d = [axis[i] + u * right[i] + v * up[i] for i in range(3)]
                n = math.sqrt(sum(c * c for c in d))
                rows[cy * side + y][cx * side + x] = tuple(encode(c) for c in radiance([c / n for c in d]))
    return w, h, rows

def png(path, w, h, rows):
    raw = b"".join(b"\0" + bytes(v for p in r for v in p) for r in rows)
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d))
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    data += chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")
    open(path, "wb").write(data)

def sky(d):
    # tests/render.rs's former sky_cube: a blue sky, a brown ground, a warm patch towards +x.
    dx, dy, _ = d
    if dx > 0.85:
        return (1.0, 0.9, 0.6)
    if dy >= 0:
        return (0.25 + 0.2 * (1 - dy), 0.4 + 0.2 * (1 - dy), 0.8)
    return (0.3, 0.2, 0.1)

SH = [5.29, 5.29, 6.404, 0.5358, 0.9645, 1.822, 0, 0, 0, 0.8573, 0.4287, 0] + [0] * 15
def irradiance(n):
    # shader.wgsl's sh_irradiance with environment_light_sh's coefficients: E(n) / π.
    x, y, z = n
    basis = [0.282095, 0.488603 * y, 0.488603 * z, 0.488603 * x, 1.092548 * x * y,
             1.092548 * y * z, 0.315392 * (3 * z * z - 1), 1.092548 * x * z, 0.546274 * (x * x - y * y)]
    return tuple(max(sum(SH[3 * i + c] * basis[i] for i in range(9)), 0) / math.pi for c in range(3))

out = sys.argv[1]
png(out + "/environment_light_specular_cross/sky_cross.png", *cross(64, sky))
png(out + "/environment_light_diffuse_cube/irradiance_cross.png", *cross(16, irradiance))
print(max(max(irradiance(d)) for d in [(0,1,0),(1,0,0),(0,0,1),(0.7,0.7,0)]))
