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
# Models behind their table (physics/model.h, struct model_ops): no file outside src/physics tests
# a model's type, so that a new model goes where docs/ARCHITECTURE.md says. Two files name each
# model on purpose: scene_keys.c, whose key table says which model each key applies to, and the
# bench's float kernel (bench/cpu_limit.c), which holds its own copy of each force law.
tests_of_models=$(grep -nE '(==|!=) *MODEL_[A-Z]+|MODEL_[A-Z]+ *(==|!=)|case MODEL_[A-Z]+' \
    $(find src -name '*.[ch]' ! -path 'src/physics/*' ! -name scene_keys.c ! -name cpu_limit.c) |
    grep -v 'MODEL_COUNT' || true)
if [ -n "$tests_of_models" ]; then
    echo "$tests_of_models" | sed 's/$/: tests a model'"'"'s type outside src\/physics: ask its model_ops (physics\/model.h)/'
    wrong=$((wrong + $(echo "$tests_of_models" | wc -l)))
fi
# One way to fail (io/error.h): no interface hands a message back through a buffer and its length
# (char *msg, size_t len; char *err, size_t; why or reason likewise); a failure fills struct error.
buffers=$(grep -nE '(char \*(msg|err|why|reason)[a-z_]*, *size_t)|(\b(msg|err|why|reason)_?len\b)' \
    $(find src -name '*.h') || true)
if [ -n "$buffers" ]; then
    echo "$buffers" | sed 's/$/: hands a message back in a buffer: fill a struct error (io\/error.h)/'
    wrong=$((wrong + $(echo "$buffers" | wc -l)))
fi
echo "layers: $checked includes checked, $wrong wrong"
[ "$wrong" = 0 ]
