# What the make_*.py scripts of the material extensions share: the 2 x 2 quad they draw (in the
# XY plane facing +Z, normals +Z; texCoord 0 with (0, 0) at the corner (-1, 1); optionally
# tangents +X and a texCoord 1 mirrored in u, u1 = 1 - u0), and PNG and data-URI writers.
import base64, struct, zlib

def png(width, height, rows, channels=3, level=-1):
    """An 8-bit PNG of `rows` (lists of bytes, one per row): RGB or RGBA."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    raw = b"".join(b"\0" + bytes(row) for row in rows)
    colour = {3: 2, 4: 6}[channels]
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, colour, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, level)) + chunk(b"IEND", b""))

def uri(data, mime):
    return "data:%s;base64,%s" % (mime, base64.b64encode(data).decode())

def quad(tangents=False, uv1=False):
    """The quad's buffer, bufferViews and accessors: POSITION, NORMAL, [TANGENT], TEXCOORD_0,
    [TEXCOORD_1], then the indices, in that order."""
    def pack(fmt, v): return struct.pack("<%d%s" % (len(v), fmt), *v)
    arrays = [(pack("f", [-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0]), 5126, 4, "VEC3"),
              (pack("f", [0, 0, 1] * 4), 5126, 4, "VEC3")]
    if tangents: arrays.append((pack("f", [1, 0, 0, 1] * 4), 5126, 4, "VEC4"))
    arrays.append((pack("f", [0, 1, 1, 1, 1, 0, 0, 0]), 5126, 4, "VEC2"))
    if uv1: arrays.append((pack("f", [1, 1, 0, 1, 0, 0, 1, 0]), 5126, 4, "VEC2"))
    arrays.append((pack("H", [0, 1, 2, 0, 2, 3]), 5123, 6, "SCALAR"))
    buf = b""; bv = []; acc = []
    for k, (data, component, count, kind) in enumerate(arrays):
        while len(buf) % 4: buf += b"\0"
        last = k == len(arrays) - 1
        bv.append({"buffer": 0, "byteOffset": len(buf), "byteLength": len(data), "target": 34963 if last else 34962}); buf += data
        acc.append({"bufferView": k, "componentType": component, "count": count, "type": kind})
    acc[0].update({"min": [-1, -1, 0], "max": [1, 1, 0]})
    return buf, bv, acc
