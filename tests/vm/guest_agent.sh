#!/bin/sh
# The virtual exhibit's agent (a service of the guest, tests/vm/bentray-vmagent.service): reads
# one shell command a line from the host's port (virtio-serial port bt.agent), runs it as root,
# and answers with its output and a line "BTVM-RC STATUS". The host's driver (tests/vm/drive.py)
# runs every check through it; nothing else reaches the guest.
port=/dev/virtio-ports/bt.agent
while [ ! -e "$port" ]; do sleep 0.2; done
exec 3<>"$port"
echo "BTVM-AGENT ready" >&3
while IFS= read -r line <&3; do
    sh -c "$line" >&3 2>&1 < /dev/null
    echo "BTVM-RC $?" >&3
done
