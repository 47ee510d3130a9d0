"""Small .vti seeds for the vti fuzz target, one per encoding the reader takes (VTK's layout:
a UInt32/UInt64 byte-count header; zlib: block count, block size, last block size, sizes).
usage: python3 make_vti_seeds.py OUT_FOLDER"""
import base64, struct, sys, zlib

out = sys.argv[1]
U = [float(v) for v in range(1, 7)]  # 2 x 1 x 1 cells, 3 components
p = [10.0, 20.0]

def raw(values, header):
    data = struct.pack(f"<{len(values)}d", *values)
    return struct.pack("<" + header, len(data)) + data, data

def zlib_blocks(values, header):
    data = struct.pack(f"<{len(values)}d", *values)
    packed = zlib.compress(data)
    return struct.pack("<" + header * 4, 1, len(data), len(data), len(packed)), packed

def image(arrays, header_type="UInt32", appended=b"", tag="CellData", compressor=""):
    head = (f'<?xml version="1.0"?>\n<VTKFile type="ImageData" version="1.0" byte_order="LittleEndian"'
            f' header_type="{header_type}"{compressor}>\n<ImageData WholeExtent="0 2 0 1 0 1" Origin="1 2 3"'
            f' Spacing="0.5 1 2">\n<Piece Extent="0 2 0 1 0 1">\n<{tag}>\n')
    text = head + "".join(arrays) + f"</{tag}>\n</Piece>\n</ImageData>\n"
    if appended:
        return text.encode() + b'<AppendedData encoding="' + appended[0] + b'">\n_' + appended[1] + b"\n</AppendedData>\n</VTKFile>\n"
    return (text + "</VTKFile>\n").encode()

def array(name, comps, fmt, body="", offset=None):
    off = f' offset="{offset}"' if offset is not None else ""
    end = "/>\n" if offset is not None else f">{body}</DataArray>\n"
    return f'<DataArray type="Float64" Name="{name}" NumberOfComponents="{comps}" format="{fmt}"{off}{end}'

seeds = {}
seeds["ascii_cell.vti"] = image([array("U", 3, "ascii", " ".join(map(str, U))), array("p", 1, "ascii", "10 20")])
points = " ".join(str(v) for v in range(12))
seeds["ascii_point.vti"] = image([array("p", 1, "ascii", points)], tag="PointData")
for h, fmt in (("UInt32", "I"), ("UInt64", "Q")):
    hu, du = raw(U, fmt); hp, dp = raw(p, fmt)
    seeds[f"base64_{h}.vti"] = image([array("U", 3, "binary", base64.b64encode(hu).decode()),
                                      array("p", 1, "binary", base64.b64encode(hp).decode())], h)
    seeds[f"appended_raw_{h}.vti"] = image([array("U", 3, "appended", offset=0),
                                            array("p", 1, "appended", offset=len(hu))], h, (b"raw", hu + hp))
    eu = base64.b64encode(hu); ep = base64.b64encode(hp)
    seeds[f"appended_base64_{h}.vti"] = image([array("U", 3, "appended", offset=0),
                                               array("p", 1, "appended", offset=len(eu))], h, (b"base64", eu + ep))
    zhu, zdu = zlib_blocks(U, fmt); zhp, zdp = zlib_blocks(p, fmt)
    comp = ' compressor="vtkZLibDataCompressor"'
    seeds[f"zlib_base64_{h}.vti"] = image(
        [array("U", 3, "binary", (base64.b64encode(zhu) + base64.b64encode(zdu)).decode()),
         array("p", 1, "binary", (base64.b64encode(zhp) + base64.b64encode(zdp)).decode())], h, compressor=comp)
    seeds[f"zlib_appended_raw_{h}.vti"] = image(
        [array("U", 3, "appended", offset=0), array("p", 1, "appended", offset=len(zhu + zdu))], h,
        (b"raw", zhu + zdu + zhp + zdp), compressor=comp)
for name, data in seeds.items():
    with open(f"{out}/{name}", "wb") as f:
        f.write(data)
