/* The harnesses that read their input as a stream of fields: take() consumes `count` bytes as a
 * little-endian integer, zeros once the input runs out (so every input is a complete one). */
#ifndef BT_FUZZ_BYTES_H
#define BT_FUZZ_BYTES_H
#include <stddef.h>
#include <stdint.h>

struct bytes {
    const uint8_t *p;
    size_t n;
};

static inline uint64_t take(struct bytes *b, int count)
{
    uint64_t v = 0;
    for (int i = 0; i < count; i++) {
        uint64_t byte = 0;
        if (b->n > 0) {
            byte = *b->p++;
            b->n--;
        }
        v |= byte << (8 * i);
    }
    return v;
}

#endif
