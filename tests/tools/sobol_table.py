#!/usr/bin/env python3
"""Writes kernels/util/sobol_table.cl: Sobol' dimensions 0-3, bit-reversed, as one 4-bit chunk
table of uint4 indexed by the bit-reversed index (one vector load per chunk for all four
dimensions), the same by dimension (sixteen consecutive words per chunk), and a byte
bit-reversal table.

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


def reverse32(x):
    return int('{:032b}'.format(x)[::-1], 2)


def main():
    dims = [[1 << (31 - k) for k in range(32)]] + [directions(*p) for p in PARAMS]
    rows = []
    by_dim = [[None] * 16 for _ in range(4 * 8)]
    # chunk k, nibble m of the reversed index r: index bits 31 - 4k - b for bits b of m
    for k in range(8):
        for m in range(16):
            lanes = []
            for v in dims:
                x = 0
                for b in range(4):
                    if (m >> b) & 1:
                        x ^= v[31 - 4 * k - b]
                lanes.append('0x%08xu' % reverse32(x))
                by_dim[8 * (len(lanes) - 1) + k][m] = lanes[-1]
            rows.append('    (uint4)(' + ', '.join(lanes) + '),')
    rev = ['0x%02xu' % int('{:08b}'.format(b)[::-1], 2) for b in range(256)]
    rev_rows = ['    ' + ', '.join(rev[i:i + 16]) + ',' for i in range(0, 256, 16)]
    dim_rows = ['    ' + ', '.join(r[:8]) + ',\n    ' + ', '.join(r[8:]) + ',' for r in by_dim]
    sys.stdout.write(HEADER + '__constant uint4 fc_sobol4_reversed[8 * 16] = {\n' + '\n'.join(rows)
                     + '\n};\n\n' + BY_DIM + '__constant uint fc_sobol_reversed_by_dim[4 * 8 * 16] = {\n'
                     + '\n'.join(dim_rows) + '\n};\n\n' + REVERSE + '__constant uchar fc_reverse_byte[256] = {\n'
                     + '\n'.join(rev_rows) + '\n};\n\n#endif\n')


HEADER = '''/* Sobol' generator matrices of dimensions 0 to 3 as one 4-bit chunk table, in the
 * bit-reversed domain of Burley's Owen scrambling (kernels/util/sampler.cl): for r the
 * bit-reversed index, lane d of entry [k][m] is the bit-reversed XOR of dimension d's
 * direction numbers of the index bits that nibble m at bit position 4k of r stands for
 * (index bits 31 - 4k - b for bit b of m), so that one uint4 load per chunk serves all
 * four dimensions and XOR-ing the chunks of r gives the reversed points directly (XOR
 * commutes with bit reversal). Generated from Joe & Kuo's direction numbers
 * ("Constructing Sobol sequences with better two-dimensional projections", SIAM J. Sci.
 * Comput. 30, 2008; the new-joe-kuo-6.21201 table: s = 1, a = 0, m = 1; s = 2, a = 1,
 * m = 1, 3; s = 3, a = 1, m = 1, 3, 1); dimension 0 is the van der Corput sequence (bit
 * reversal). Regenerate with tests/tools/sobol_table.py. */
#ifndef FACET_UTIL_SOBOL_TABLE_CL
#define FACET_UTIL_SOBOL_TABLE_CL

'''

BY_DIM = '''/* The same table by dimension: entry [d][k][m] is lane d of fc_sobol4_reversed[k][m], so
 * that chunk k of dimension d is sixteen consecutive words, one 512-bit register, which the
 * packets' sampler indexes by sixteen nibbles at once (kernels/util/sampler_lanes.cl). */
'''

REVERSE = '''/* Each byte with its bits in reverse order. A table rather than the five shift-and-mask
 * steps, which compilers turn into llvm.bitreverse, an intrinsic that some OpenCL
 * implementations (Oclgrind 21.10) cannot run. */
'''

if __name__ == '__main__':
    main()
