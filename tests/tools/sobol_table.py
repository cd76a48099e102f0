#!/usr/bin/env python3
"""Writes kernels/util/sobol_table.cl: Sobol' dimensions 1-3 as 4-bit chunk tables,
and a byte bit-reversal table.

Direction numbers from Joe & Kuo 2008 (new-joe-kuo-6.21201), first three rows:
s = 1, a = 0, m = 1;  s = 2, a = 1, m = 1, 3;  s = 3, a = 1, m = 1, 3, 1.
Usage (from the root): python3 tests/tools/sobol_table.py > kernels/util/sobol_table.cl && make format
"""
import sys

PARAMS = [(1, 0, [1]), (2, 1, [1, 3]), (3, 1, [1, 3, 1])]


def directions(s, a, m):
    v = [0] * 33
    for k in range(1, s + 1):
        v[k] = m[k - 1] << (32 - k)
    for k in range(s + 1, 33):
        x = v[k - s] ^ (v[k - s] >> s)
        for j in range(1, s):
            if (a >> (s - 1 - j)) & 1:
                x ^= v[k - j]
        v[k] = x
    return v[1:]


def main():
    blocks = []
    for d, p in enumerate(PARAMS, start=1):
        v = directions(*p)
        rows = []
        for c in range(8):
            ent = []
            for n in range(16):
                x = 0
                for b in range(4):
                    if (n >> b) & 1:
                        x ^= v[4 * c + b]
                ent.append('0x%08xu' % x)
            rows.append('    ' + ', '.join(ent[:8]) + ',\n    ' + ', '.join(ent[8:]) + ',')
        blocks.append('    /* dimension %d */\n' % d + '\n'.join(rows))
    rev = ['0x%02xu' % int('{:08b}'.format(b)[::-1], 2) for b in range(256)]
    rev_rows = ['    ' + ', '.join(rev[i:i + 16]) + ',' for i in range(0, 256, 16)]
    sys.stdout.write(HEADER + '__constant uint fc_sobol_chunks[3 * 8 * 16] = {\n' + '\n'.join(blocks)
                     + '\n};\n\n' + REVERSE + '__constant uchar fc_reverse_byte[256] = {\n'
                     + '\n'.join(rev_rows) + '\n};\n\n#endif\n')


HEADER = '''/* Sobol' generator matrices of dimensions 1 to 3 as 4-bit chunk tables: entry
 * [d - 1][c][n] is the XOR of the direction numbers of the set bits of nibble n at bit
 * position 4c of the index. Generated from Joe & Kuo's direction numbers ("Constructing
 * Sobol sequences with better two-dimensional projections", SIAM J. Sci. Comput. 30,
 * 2008; the new-joe-kuo-6.21201 table: s = 1, a = 0, m = 1; s = 2, a = 1, m = 1, 3;
 * s = 3, a = 1, m = 1, 3, 1). Dimension 0 is the van der Corput sequence (bit
 * reversal) and needs no table. Regenerate with tests/tools/sobol_table.py. */
#ifndef FACET_UTIL_SOBOL_TABLE_CL
#define FACET_UTIL_SOBOL_TABLE_CL

'''

REVERSE = '''/* Each byte with its bits in reverse order. A table rather than the five shift-and-mask
 * steps, which compilers turn into llvm.bitreverse, an intrinsic that some OpenCL
 * implementations (Oclgrind 21.10) cannot run. */
'''

if __name__ == '__main__':
    main()
