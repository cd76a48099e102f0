/* kernels/test/packet_trace_kernels.cl in packets of 8. */
#define FC_PACKET_WIDTH 8
#include "kernels/test/packet_trace_kernels.cl"
