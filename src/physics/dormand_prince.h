/* Dormand and Prince's RK5(4)7M tableau (Dormand & Prince 1980; Hairer, Norsett, Wanner, Table
 * II.5.2), the one copy that the model's fixed step, the orbit table's Binet integration and the CPU
 * reference share. shaders_es/stage_integrate.glsl writes the same numbers in GLSL. The nodes c_i are
 * not needed: no model depends on the curve parameter itself. */
#ifndef BT_DORMAND_PRINCE_H
#define BT_DORMAND_PRINCE_H

/* a[s - 1][j]: stage s (1..6) from stage j (0..s-1); the last row is the fifth-order weights b
 * (the first-same-as-last property: stage 7 is evaluated at the new state). */
extern const double dormand_prince_a[6][6];
/* b - b*: the weights of the order-4 error estimate over the seven stages */
extern const double dormand_prince_e[7];

#endif
