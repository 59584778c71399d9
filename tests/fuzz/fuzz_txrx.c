/* fuzz_txrx.c - libFuzzer target: the device's receive parser (r8_tx_rx)
 * fed arbitrary display -> device bytes.  Checks: it never reads or
 * writes outside r8_tx (ASan), its result is 0, REQUEST or INPUT, an
 * INPUT result changes the keys to what the packet says and counts it,
 * and nothing else changes keys or the request flag. */
#include <stdlib.h>
#include <string.h>
#include "r8wire.h"

static void sink(void *ctx, const r8_u8 *p, unsigned n)
{
    (void)ctx;
    (void)p;
    (void)n;
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
    static r8_u8 scratch[256];
    r8_tx_cfg c;
    r8_tx tx;
    size_t i;
    memset(&c, 0, sizeof c);
    c.format = R8_FMT_PAGE1;
    c.width = 16;
    c.height = 8;
    c.band = 8;
    c.codec = R8_CODEC_RLE;
    if (r8_tx_init(&tx, &c, scratch, sizeof scratch, sink, 0))
        abort();
    tx.want_full = 0;
    for (i = 0; i < size; i++) {
        r8_u16 keys = tx.keys, inputs = tx.inputs;
        r8_u8 want = tx.want_full;
        int r = r8_tx_rx(&tx, data[i]);
        if (r != 0 && r != R8_RX_REQUEST && r != R8_RX_INPUT)
            abort();
        if (r != 0 && data[i] != 0)
            abort(); /* a packet ends only at its 0x00 */
        if (r == R8_RX_INPUT) {
            if ((r8_u16)(inputs + 1u) != tx.inputs)
                abort();
        } else if (tx.keys != keys || tx.inputs != inputs) {
            abort();
        }
        if (r == R8_RX_REQUEST ? !tx.want_full : tx.want_full != want)
            abort();
    }
    return 0;
}
