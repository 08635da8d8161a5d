#!/usr/bin/env python3
"""Writes the malformed-file corpus of tests/stress_bad_files_test.cpp (README "Robustness", bad
files). The files are committed; this script documents how each was made and can rewrite them."""
import base64, json, os, struct, zlib

here = os.path.dirname(os.path.abspath(__file__))


def write(name, data):
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(here, name), 'wb') as f:
        f.write(data)


def png(width, height, rows=None, truncate=None):
    def chunk(kind, body):
        return struct.pack('>I', len(body)) + kind + body + struct.pack('>I', zlib.crc32(kind + body) & 0xffffffff)
    ihdr = struct.pack('>IIBBBBB', width, height, 8, 6, 0, 0, 0)
    data = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', ihdr)
    if rows is not None:
        data += chunk(b'IDAT', zlib.compress(rows)) + chunk(b'IEND', b'')
    return data[:truncate] if truncate else data


good_png = png(2, 2, b''.join(b'\x00' + b'\xff\x80\x40\xff' * 2 for _ in range(2)))

# A unit quad: positions, normals, uvs, indices (little-endian float32 / uint16).
positions = struct.pack('<12f', 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0)
normals = struct.pack('<12f', *([0, 0, 1] * 4))
uvs = struct.pack('<8f', 0, 0, 1, 0, 1, 1, 0, 1)
indices = struct.pack('<6H', 0, 1, 2, 0, 2, 3)
blob = positions + normals + uvs + indices


def gltf(buffer_uri=None, byte_length=None, count=4, index_values=None, images=None, extra=None, view_of_indices=3,
         nodes=None, mesh_index=0, version='2.0'):
    data = positions + normals + uvs + (struct.pack('<6H', *index_values) if index_values else indices)
    uri = buffer_uri if buffer_uri is not None else 'data:application/octet-stream;base64,' + base64.b64encode(data).decode()
    doc = {
        'asset': {'version': version},
        'scenes': [{'nodes': [0]}], 'scene': 0,
        'nodes': nodes or [{'mesh': mesh_index}],
        'meshes': [{'primitives': [{'attributes': {'POSITION': 0, 'NORMAL': 1, 'TEXCOORD_0': 2}, 'indices': 3,
                                    'material': 0}]}],
        'materials': [{'pbrMetallicRoughness': {'baseColorFactor': [0.8, 0.8, 0.8, 1]}}],
        'buffers': [{'byteLength': byte_length if byte_length is not None else len(data), 'uri': uri}],
        'bufferViews': [{'buffer': 0, 'byteLength': 48}, {'buffer': 0, 'byteOffset': 48, 'byteLength': 48},
                        {'buffer': 0, 'byteOffset': 96, 'byteLength': 32},
                        {'buffer': 0, 'byteOffset': 128, 'byteLength': 12}],
        'accessors': [
            {'bufferView': 0, 'componentType': 5126, 'count': count, 'type': 'VEC3', 'min': [0, 0, 0], 'max': [1, 1, 0]},
            {'bufferView': 1, 'componentType': 5126, 'count': 4, 'type': 'VEC3'},
            {'bufferView': 2, 'componentType': 5126, 'count': 4, 'type': 'VEC2'},
            {'bufferView': view_of_indices, 'componentType': 5123, 'count': 6, 'type': 'SCALAR'}],
    }
    if images:
        doc['images'] = images
        doc['textures'] = [{'source': 0}]
        doc['materials'][0]['pbrMetallicRoughness']['baseColorTexture'] = {'index': 0}
    if extra:
        extra(doc)
    return json.dumps(doc, indent=1)


full = gltf()
write('gltf_truncated.gltf', full[:len(full) // 2])
write('gltf_not_json.gltf', bytes(range(256)) * 2)
write('gltf_empty.gltf', b'')
write('gltf_version_1.gltf', gltf(version='1.0'))
write('gltf_missing_buffer.gltf', gltf(buffer_uri='missing.bin'))
write('gltf_short_buffer.gltf', gltf(byte_length=100000))
write('gltf_huge_count.gltf', gltf(count=4000000000))
write('gltf_bad_indices.gltf', gltf(index_values=[0, 1, 2, 0, 2, 999]))
write('gltf_bad_buffer_view.gltf', gltf(view_of_indices=7))
write('gltf_bad_base64.gltf', gltf(buffer_uri='data:application/octet-stream;base64,!!!not*base64***'))
write('gltf_mesh_out_of_range.gltf', gltf(mesh_index=5))
write('gltf_node_cycle.gltf', gltf(nodes=[{'mesh': 0, 'children': [1]}, {'children': [0]}]))
write('gltf_missing_texture.gltf', gltf(images=[{'uri': 'nothere.png'}]))
write('gltf_corrupt_texture.gltf',
      gltf(images=[{'uri': 'data:image/png;base64,' + base64.b64encode(b'\x89PNG garbage' * 4).decode()}]))
write('gltf_huge_texture.gltf',
      gltf(images=[{'uri': 'data:image/png;base64,' + base64.b64encode(png(65535, 65535)).decode()}]))
write('gltf_negative_count.gltf', gltf(count=-3))

glb_json = gltf().encode()
glb_json += b' ' * ((4 - len(glb_json) % 4) % 4)
glb = struct.pack('<III', 0x46546C67, 2, 12 + 8 + len(glb_json)) + struct.pack('<II', len(glb_json), 0x4E4F534A) + glb_json
write('glb_wrong_magic.glb', b'GLTX' + glb[4:])
write('glb_truncated.glb', glb[:20])
write('glb_huge_chunk.glb', glb[:12] + struct.pack('<II', 0xFFFFFFF0, 0x4E4F534A) + glb_json[:64])

quad = 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n'
write('obj_face_out_of_range.obj', quad + 'f 1 2 3\nf 1 2 99999999999\n')
write('obj_negative_index.obj', quad + 'f -1 -2 -50\nf 1 2 3\n')
write('obj_only_vertices.obj', quad)
write('obj_garbage.obj', bytes((i * 37 + 11) % 256 for i in range(700)))
write('obj_empty.obj', b'')
write('obj_infinite_vertex.obj', 'v 0 0 0\nv 1e999 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 1 4 3\n')
write('obj_missing_mtl.obj', 'mtllib nothere.mtl\nusemtl wall\n' + quad + 'f 1 2 3\nf 1 3 4\n')
write('obj_unknown_material.obj', 'mtllib bad.mtl\nusemtl nosuch\n' + quad + 'f 1 2 3\nf 1 3 4\n')
write('obj_bad_mtl.obj', 'mtllib bad.mtl\nusemtl broken\n' + quad + 'f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n')
write('bad.mtl', 'newmtl broken\nKd nan 0.5 inf\nKe -4 1e999 0\nd nan\nmap_Kd png_truncated.png\nmap_d png_wrong_magic.png\n'
      '\x00\x01\x02 garbage line\nnewmtl\n')
# Assimp 5.2 crashes on a texture statement before any newmtl (found by tests/fuzz).
write('obj_mtl_before_newmtl.obj', 'mtllib before_newmtl.mtl\nusemtl late\n' + quad + 'f 1 2 3\nf 1 3 4\n')
write('before_newmtl.mtl', '# a texture with no material yet\nmap_Kd png_truncated.png\nnewmtl late\nKd 1 1 1\n')
write('obj_bad_texcoord_refs.obj', quad + 'vn 0 0 1\nf 1/9/9 2/10/1 3/3/77\nf 1/1 3/3 4/4\n')

write('png_truncated.png', good_png[:40])
write('png_wrong_magic.png', b'\x89PNX' + good_png[4:])
write('png_huge_dims.png', png(100000, 100000, truncate=None))
write('png_zero_size.png', png(0, 0, b''))
write('jpg_truncated.jpg', b'\xff\xd8\xff\xe0\x00\x10JFIF\x00\x01\x01\x00\x00\x01\x00\x01\x00\x00\xff\xc0\x00\x11\x08\xff\xff\xff\xff')
# 19 bytes declaring 9265x12576 uncompressed texels: stb_image would allocate 466 MB (1 GB and 3 s
# in all) before finding the file empty; refused from the header (engine/scene/image_payload.hpp).
write('tga_huge_dims.tga', struct.pack('<BBBHHBHHHHBB', 0, 0, 2, 0, 0, 0, 0, 0, 9265, 12576, 24, 0) + b'\x00')
write('bmp_huge_dims.bmp', b'BM' + struct.pack('<IHHI', 54, 0, 0, 54) +
      struct.pack('<IiiHHIIiiII', 40, 60000, 60000, 1, 32, 0, 0, 2835, 2835, 0, 0))
