/* kernels/test/packet_trace_kernels.cl in packets of 8, quantised nodes. */
#define FC_PACKET_WIDTH 8
#define FC_BVH_QUANTISED 1
#include "kernels/test/packet_trace_kernels.cl"
