#!/bin/sh
# The modules of src/ and what each may include (docs/ARCHITECTURE.md): a lower module never
# includes a higher one. Fails, naming the file and the include, when one does, and when a file
# includes a module this table does not know.
# Prints "layers: N includes checked, M wrong"; exit 0 when none is wrong.
cd "$(dirname "$0")/.." || exit 1
allowed() {
    case $1 in
        io) echo "" ;;
        physics) echo "io" ;;
        gl) echo "io" ;;
        conf) echo "io" ;;
        scene) echo "io physics conf" ;;
        results) echo "io physics scene" ;;
        ref) echo "io physics scene results" ;;
        render) echo "io physics gl scene results" ;;
        input) echo "io" ;;
        display) echo "io gl input" ;;
        kiosk_config) echo "io conf scene input display" ;;
        kiosk) echo "io physics gl conf scene render kiosk_config input display" ;;
        bench) echo "io physics gl conf scene results ref render kiosk_config input display kiosk" ;;
        cli) echo "io physics gl conf scene results ref render kiosk_config input display kiosk bench" ;;
        tools) echo "io physics gl conf scene results ref render cli" ;;
        *) echo "?" ;;
    esac
}
checked=0
wrong=0
for dir in src/*/; do
    module=$(basename "$dir")
    ok=$(allowed "$module")
    if [ "$ok" = "?" ]; then
        echo "unknown module src/$module: give it its place in tests/check_layers.sh and docs/ARCHITECTURE.md"
        wrong=$((wrong + 1))
        continue
    fi
    for f in "$dir"*.c "$dir"*.h; do
        [ -e "$f" ] || continue
        for dep in $(sed -n 's/^#include "\([a-z_]*\)\/.*/\1/p' "$f"); do
            checked=$((checked + 1))
            [ "$dep" = "$module" ] && continue
            case " $ok " in
                *" $dep "*) ;;
                *) echo "$f includes $dep/: $module may include only: ${ok:-nothing of src/}"; wrong=$((wrong + 1)) ;;
            esac
        done
    done
done
echo "layers: $checked includes checked, $wrong wrong"
[ "$wrong" = 0 ]
