/* kernels/test/packet_trace_kernels.cl in packets of 16. */
#define FC_PACKET_WIDTH 16
#include "kernels/test/packet_trace_kernels.cl"
