"""A small binary-PGM (P5, 8-bit) reader, independent of linemap's."""
import numpy as np


def read_pgm(path):
    """The image as a uint8 array (rows, cols), image row 0 at the top."""
    data = open(path, "rb").read()
    fields = []
    pos = 0
    while len(fields) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":  # a comment runs to the end of the line
            while data[pos:pos + 1] not in (b"\n", b"\r"):
                pos += 1
            continue
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        fields.append(data[start:pos])
    pos += 1  # the single whitespace byte after maxval
    magic, width, height, maxval = fields[0], int(fields[1]), int(fields[2]), int(fields[3])
    assert magic == b"P5" and maxval < 256, (magic, maxval)
    pixels = np.frombuffer(data, dtype=np.uint8, count=width * height, offset=pos)
    return pixels.reshape(height, width)


def cells_of_map_saver_pgm(path, free=0, occupied=1, unknown=2):
    """Cells (grid rows, row 0 at the origin) of a PGM as map_saver writes it
    in trinary mode: 0 occupied, 254 free, 205 unknown."""
    image = read_pgm(path)
    values = set(np.unique(image).tolist())
    assert values <= {0, 205, 254}, values
    cells = np.full(image.shape, unknown, dtype=np.uint8)
    cells[image == 0] = occupied
    cells[image == 254] = free
    return cells[::-1]  # image row 0 is the top of the map
