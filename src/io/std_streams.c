#include "io/std_streams.h"
#include <errno.h>
#include <fcntl.h>
#include <unistd.h>

static int stdout_closed;

void std_streams_guard(void)
{
    for (int fd = 0; fd <= 2; fd++) {
        if (fcntl(fd, F_GETFD) != -1 || errno != EBADF)
            continue;
        /* open() takes the lowest free number: this one, as the lower ones are open by now */
        int got = open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
        if (got >= 0 && got != fd) {
            dup2(got, fd);
            close(got);
        }
        if (fd == 1)
            stdout_closed = 1;
    }
}

int std_stdout_closed(void)
{
    return stdout_closed;
}
