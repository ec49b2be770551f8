/* Orbit tables kept by what they depend on (struct orbit_table_params), and built ahead.
 *
 * A table depends on the mass, the camera's radius and the scene's sizes, so the kiosk's mass knob
 * asks for a new one at every detent. The store keeps every table it built, up to a memory budget,
 * and a worker thread builds the tables a caller expects to need next (orbit_store_prefetch: the
 * detents beside the knob's), so that a detent finds its table built and costs an upload. A table
 * is a pure function of its parameters: one built by the worker is the one a fresh render builds,
 * bit for bit. The store keeps each table's texels only (what the GPU reads). */
#ifndef BT_ORBIT_STORE_H
#define BT_ORBIT_STORE_H
#include <stddef.h>
#include "io/error.h"
#include "physics/orbit_table.h"

/* What a store keeps at most, bytes of texels: 81 preview tables of the kiosk (the shipped mass
 * knob's detents, 0.27 MB each) and a dozen refined ones (2.6 MB each) */
#define ORBIT_STORE_BUDGET ((size_t)64 << 20)

struct orbit_store;

/* An empty store (its worker starts at the first prefetch); NULL with e when out of memory. */
struct orbit_store *orbit_store_create(size_t budget, struct error *e);
/* The store goes; a table the worker is building is finished and dropped by the worker itself,
 * so that this never waits for it. */
void orbit_store_destroy(struct orbit_store *s);
/* The table for p, its texels valid until the next call on this store: kept, or waited for where
 * the worker is building it, or built now. NULL with e: orbit_table_build's failure. */
const struct orbit_table *orbit_store_get(struct orbit_store *s, const struct orbit_table_params *p,
                                          struct error *e);
/* A table larger than this is not built ahead (its build would hold the worker for seconds: the
 * largest orbit_rows and orbit_columns take about 19 s here); orbit_store_get builds it. */
#define ORBIT_STORE_AHEAD_MAX_BYTES ((size_t)8 << 20)
/* Build these tables in the background, first to last, in place of what was still waiting: those
 * beyond the budget, and any one over ORBIT_STORE_AHEAD_MAX_BYTES, are left to orbit_store_get. */
void orbit_store_prefetch(struct orbit_store *s, const struct orbit_table_params *p, int n);
/* Tables waiting for the worker or being built (0: it is idle). */
int orbit_store_pending(struct orbit_store *s);
/* Seconds the callers of orbit_store_get spent building tables or waiting for them. */
double orbit_store_caller_seconds(const struct orbit_store *s);
/* Tables the callers of orbit_store_get built themselves (none was kept or being built). */
int orbit_store_caller_builds(const struct orbit_store *s);
/* Bytes of texels kept now. */
size_t orbit_store_bytes(struct orbit_store *s);
/* Whether two tables would be the same: their parameters field by field. */
int orbit_params_same(const struct orbit_table_params *a, const struct orbit_table_params *b);
/* Bytes of texels a table for p holds (its share of the budget). */
size_t orbit_store_table_bytes(const struct orbit_table_params *p);

#endif
