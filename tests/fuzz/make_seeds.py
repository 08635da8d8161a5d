#!/usr/bin/env python3
"""Writes the committed seed corpus of fuzz_loader (tests/fuzz/corpus): small valid files of each
format and a few of tests/data/bad, each prefixed by the format byte fuzz_loader.cpp expects."""
import base64, json, os, struct, zlib

here = os.path.dirname(os.path.abspath(__file__))
corpus = os.path.join(here, 'corpus')
bad = os.path.join(here, '..', 'data', 'bad')
os.makedirs(corpus, exist_ok=True)


def seed(name, mode, data):
    with open(os.path.join(corpus, name), 'wb') as f:
        f.write(bytes([mode]) + (data.encode() if isinstance(data, str) else data))


def png(width, height, pixel=b'\xff\x80\x40\xff'):
    def chunk(kind, body):
        return struct.pack('>I', len(body)) + kind + body + struct.pack('>I', zlib.crc32(kind + body) & 0xffffffff)
    rows = b''.join(b'\x00' + pixel * width for _ in range(height))
    return (b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, 8, 6, 0, 0, 0)) +
            chunk(b'IDAT', zlib.compress(rows)) + chunk(b'IEND', b''))


data = (struct.pack('<12f', 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0) + struct.pack('<12f', *([0, 0, 1] * 4)) +
        struct.pack('<8f', 0, 0, 1, 0, 1, 1, 0, 1) + struct.pack('<6H', 0, 1, 2, 0, 2, 3))
doc = {
    'asset': {'version': '2.0'}, 'scenes': [{'nodes': [0, 1, 2]}], 'scene': 0,
    'nodes': [{'mesh': 0, 'translation': [0, 0, -1], 'scale': [2, 2, 2]},
              {'camera': 0, 'translation': [0.5, 0.5, 3]},
              {'extensions': {'KHR_lights_punctual': {'light': 0}}, 'rotation': [-0.707, 0, 0, 0.707]}],
    'cameras': [{'type': 'perspective', 'perspective': {'yfov': 0.8, 'znear': 0.1, 'aspectRatio': 1.5}}],
    'extensionsUsed': ['KHR_lights_punctual'],
    'extensions': {'KHR_lights_punctual': {'lights': [{'type': 'spot', 'intensity': 5, 'color': [1, 0.9, 0.8],
                                                       'spot': {'innerConeAngle': 0.3, 'outerConeAngle': 0.6}}]}},
    'meshes': [{'primitives': [{'attributes': {'POSITION': 0, 'NORMAL': 1, 'TEXCOORD_0': 2}, 'indices': 3, 'material': 0}]}],
    'materials': [{'pbrMetallicRoughness': {'baseColorFactor': [0.8, 0.7, 0.6, 1], 'baseColorTexture': {'index': 0}},
                   'emissiveFactor': [0.1, 0, 0], 'alphaMode': 'MASK', 'alphaCutoff': 0.5}],
    'textures': [{'source': 0}],
    'images': [{'uri': 'data:image/png;base64,' + base64.b64encode(png(2, 2)).decode()}],
    'buffers': [{'byteLength': len(data), 'uri': 'data:application/octet-stream;base64,' + base64.b64encode(data).decode()}],
    'bufferViews': [{'buffer': 0, 'byteLength': 48}, {'buffer': 0, 'byteOffset': 48, 'byteLength': 48},
                    {'buffer': 0, 'byteOffset': 96, 'byteLength': 32}, {'buffer': 0, 'byteOffset': 128, 'byteLength': 12}],
    'accessors': [
        {'bufferView': 0, 'componentType': 5126, 'count': 4, 'type': 'VEC3', 'min': [0, 0, 0], 'max': [1, 1, 0]},
        {'bufferView': 1, 'componentType': 5126, 'count': 4, 'type': 'VEC3'},
        {'bufferView': 2, 'componentType': 5126, 'count': 4, 'type': 'VEC2'},
        {'bufferView': 3, 'componentType': 5123, 'count': 6, 'type': 'SCALAR'}],
}
text = json.dumps(doc)
seed('quad.gltf', 0, text)

glb_doc = dict(doc)
glb_doc['buffers'] = [{'byteLength': len(data)}]
js = json.dumps(glb_doc).encode()
js += b' ' * ((4 - len(js) % 4) % 4)
binary = data + b'\0' * ((4 - len(data) % 4) % 4)
glb = (struct.pack('<III', 0x46546C67, 2, 12 + 8 + len(js) + 8 + len(binary)) + struct.pack('<II', len(js), 0x4E4F534A) + js +
       struct.pack('<II', len(binary), 0x004E4942) + binary)
seed('quad.glb', 1, glb)

obj = ('mtllib model.mtl\no box\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n'
       'usemtl red\nf 1/1/1 2/2/1 3/3/1 4/1/1\ng side\nusemtl glow\nf 1 2 6 5\nf -1 -2 -3\n')
mtl = 'newmtl red\nKd 0.8 0.1 0.1\nd 1\nnewmtl glow\nKd 0 0 0\nKe 2 2 2\nmap_Kd tex.png\n'
seed('box.obj', 2, obj + '\n#MTL\n' + mtl)
seed('png.img', 3, png(3, 2))
seed('bmp.img', 3, b'BM' + struct.pack('<IHHI', 54 + 16, 0, 0, 54) +
     struct.pack('<IiiHHIIiiII', 40, 2, 2, 1, 32, 0, 16, 2835, 2835, 0, 0) + b'\x10\x20\x30\xff' * 4)
seed('tga.img', 3, struct.pack('<BBBHHBHHHHBB', 0, 0, 2, 0, 0, 0, 0, 0, 2, 2, 24, 0) + b'\x10\x20\x30' * 4)
for name, mode in [('gltf_bad_indices.gltf', 0), ('gltf_node_cycle.gltf', 0), ('glb_huge_chunk.glb', 1),
                   ('obj_negative_index.obj', 2), ('obj_bad_texcoord_refs.obj', 2), ('png_huge_dims.png', 3)]:
    with open(os.path.join(bad, name), 'rb') as f:
        seed(name, mode, f.read())
# The first crash fuzz_loader found (a texture statement before any newmtl), kept as a regression seed.
seed('obj_mtl_before_newmtl.obj', 2, 'mtllib model.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n#MTL\nmap_Kd tex.png\n')
