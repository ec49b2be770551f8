/* Sub-commands of the bentray binary. Each returns the process exit code. */
#ifndef BT_COMMANDS_H
#define BT_COMMANDS_H

/* EXIT_QUALITY: `bentray error --check` found the scene missing its own [quality] */
enum exit_code { EXIT_OK = 0, EXIT_RUNTIME = 1, EXIT_USAGE = 2, EXIT_QUALITY = 3 };

struct error;
/* The exit code of a failure: EXIT_USAGE where it is the user's (ERROR_INPUT), else EXIT_RUNTIME. */
enum exit_code exit_code_of(const struct error *e);

int cmd_info(int argc, char **argv);
int cmd_render(int argc, char **argv);
int cmd_trace(int argc, char **argv);
int cmd_animate(int argc, char **argv);
int cmd_compare(int argc, char **argv);
int cmd_error(int argc, char **argv);
int cmd_bench(int argc, char **argv);
int cmd_kiosk(int argc, char **argv);

#endif
