#!/bin/sh
# After a `make fuzz` run: adds its numbers to the running totals (docs/fuzz_totals.csv, one line per
# target, meant to be committed) and writes docs/RELIABILITY.md from the run's logs and the totals.
#
#   tests/fuzz/report.sh FUZZ_DIR SECONDS TARGET...
#
# FUZZ_DIR holds logs/TARGET.log (libFuzzer's output, run with -print_final_stats=1),
# logs/TARGET.rc (its exit status) and corpus/TARGET/. BT_FUZZ_TOTALS and BT_FUZZ_REPORT name other
# files for the totals and the report (for trying this script out).
set -eu

if [ $# -lt 3 ]; then
    echo "usage: $0 FUZZ_DIR SECONDS TARGET..." >&2
    exit 2
fi
dir=$1
seconds=$2
shift 2
totals=${BT_FUZZ_TOTALS:-docs/fuzz_totals.csv}
report=${BT_FUZZ_REPORT:-docs/RELIABILITY.md}
# the run's time: when its last target ended (so that the report can be written again from the same logs)
last_rc=$(ls -t "$dir"/logs/*.rc 2>/dev/null | head -n 1 || true)
now=$(date -u -r "$last_rc" +%Y-%m-%dT%H:%M:%SZ 2>/dev/null || date -u +%Y-%m-%dT%H:%M:%SZ)
header="target,runs,executions,seconds,crashes,first_run,last_run"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# ---- this run, one line per target: target|executions|seconds|rc|files|bytes|artifact|summary ----

for t in "$@"; do
    log=$dir/logs/$t.log
    rc=$(cat "$dir/logs/$t.rc" 2>/dev/null || echo 127)
    [ -f "$log" ] || : > "$work/empty.log"
    [ -f "$log" ] || log=$work/empty.log
    execs=$(sed -n 's/^stat::number_of_executed_units: *\([0-9]*\).*/\1/p' "$log" | tail -n 1)
    # no final statistics (killed): the last status line, "#N ..."
    [ -n "$execs" ] || execs=$(sed -n 's/^#\([0-9][0-9]*\).*/\1/p' "$log" | tail -n 1)
    [ -n "$execs" ] || execs=0
    secs=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -n 1)
    if [ -z "$secs" ]; then
        rate=$(sed -n 's/^stat::average_exec_per_sec: *\([0-9]*\).*/\1/p' "$log" | tail -n 1)
        if [ -n "$rate" ] && [ "$rate" -gt 0 ]; then secs=$((execs / rate)); else secs=0; fi
    fi
    corpus=$dir/corpus/$t
    files=$(find "$corpus" -type f 2>/dev/null | wc -l | tr -d ' ')
    bytes=$(find "$corpus" -type f -exec cat {} + 2>/dev/null | wc -c | tr -d ' ')
    artifact=$(sed -n 's/^.*Test unit written to //p' "$log" | tail -n 1)
    summary=$(sed -n 's/^SUMMARY: //p' "$log" | head -n 1 | tr '|' '/')
    if [ "$rc" != 0 ] && [ -z "$summary" ]; then
        summary=$(grep -m1 'ERROR:\|runtime error:\|deadly signal' "$log" | tr '|' '/' || true)
        [ -n "$summary" ] || summary="exit status $rc"
    fi
    echo "$t|$execs|$secs|$rc|$files|$bytes|$artifact|$summary" >> "$work/run"
done

# ---- the running totals -------------------------------------------------------------------------

if [ -f "$totals" ]; then
    tail -n +2 "$totals" > "$work/old"
else
    : > "$work/old"
fi
awk -F'|' -v OFS=, -v now="$now" -v old="$work/old" '
    FILENAME == old { split($0, f, ","); runs[f[1]] = f[2]; ex[f[1]] = f[3]; sec[f[1]] = f[4];
                cr[f[1]] = f[5]; first[f[1]] = f[6]; last[f[1]] = f[7]; order[++n] = f[1]; next }
    {
        t = $1
        if (!(t in runs)) { order[++n] = t; runs[t] = 0; ex[t] = 0; sec[t] = 0; cr[t] = 0; first[t] = now }
        runs[t]++; ex[t] += $2; sec[t] += $3; if ($4 != 0) cr[t]++; last[t] = now
    }
    END { for (i = 1; i <= n; i++) { t = order[i]; print t, runs[t], ex[t], sec[t], cr[t], first[t], last[t] } }
' "$work/old" "$work/run" > "$work/new"
mkdir -p "$(dirname "$totals")"
{ echo "$header"; cat "$work/new"; } > "$totals.tmp"
mv "$totals.tmp" "$totals"

# ---- docs/RELIABILITY.md --------------------------------------------------------------------------

feeds() {
    case $1 in
    conf) echo "the configuration reader and its values, on a schema of its own: conf_read, conf_parse_numbers, conf_parse_integer" ;;
    scene) echo "scene files: scene_load, scene_validate, scene_set" ;;
    kiosk_config) echo "kiosk configuration: kiosk_config_load, kiosk_config_check" ;;
    dump) echo "per-pixel dumps: dump_read, dump_write" ;;
    hid) echo "HID reports and layouts: hid_layout_check, hid_decode, powermate_decode, counter_delta" ;;
    gpio) echo "GPIO edge streams: quadrature, debounce, event_merge" ;;
    script) echo "kiosk scripts and the attract tour: script_load, script_player" ;;
    *) echo "-" ;;
    esac
}

# the source the harnesses were built from (written when their library was built), else today's
if [ -s "$dir/source" ]; then
    commit=$(cat "$dir/source")
else
    commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
    if [ -n "$(git status --porcelain -- src 2>/dev/null)" ]; then commit="$commit (with uncommitted changes in src/)"; fi
fi
compiler=$(clang --version 2>/dev/null | head -n 1 || echo "clang")
failed=$(awk -F'|' '$4 != 0' "$work/run" | wc -l | tr -d ' ')

{
    echo "# Reliability: fuzzing"
    echo
    echo "Written by \`tests/fuzz/report.sh\` at the end of \`make fuzz\`; edit the script, not this file."
    echo
    echo "The kiosk runs unattended and reads files that exhibition staff edit (scene files, the kiosk"
    echo "configuration) and whatever its knobs send. Each reader of such input has a libFuzzer harness"
    echo "(\`tests/fuzz/fuzz_TARGET.c\`, its name in the Makefile's FUZZ_TARGETS; it links what it calls"
    echo "from one library of the modules below the GL code), built with clang under AddressSanitizer and"
    echo "UndefinedBehaviorSanitizer (undefined behaviour stops the run); a run fails on a crash, a"
    echo "sanitizer report, a leak, an input slower than FUZZ_TIMEOUT (10 s unless a loaded machine's run"
    echo "asks for more), more than 2 GB asked for at once, or a"
    echo "broken invariant of the harness (\`__builtin_trap()\`). \`make fuzz FUZZ_SECONDS=N\` runs each"
    echo "for N seconds (default 60) and rewrites this file; \`make fuzz-smoke\` runs each for 5 seconds"
    echo "and writes nothing outside \`build/\`. Neither is part of \`make test\`."
    echo
    echo "## Last run"
    echo
    echo "$now, $seconds s per target, $compiler, source $commit."
    if [ "$failed" = 0 ]; then
        echo "No target failed."
    else
        echo "**$failed target(s) failed**: see the result column and the reproducers below."
    fi
    echo
    echo "| target | input | executions, this run | executions, all runs (runs) | corpus | result |"
    echo "|---|---|---:|---:|---:|---|"
    while IFS='|' read -r t execs secs rc files bytes artifact summary; do
        all=$(awk -F, -v t="$t" '$1 == t { print $3 " (" $2 ")" }' "$totals")
        if [ "$rc" = 0 ]; then
            result="no crash"
        elif [ -n "$artifact" ]; then
            result="**$summary**: \`$(basename "$artifact")\`"
        else
            result="**$summary** (no reproducer written)"
        fi
        echo "| $t | $(feeds "$t") | $execs in $secs s | $all | $files inputs, $((bytes / 1024)) KB | $result |"
    done < "$work/run"
    echo
    echo "Totals over every \`make fuzz\` run so far are kept in \`$totals\`"
    echo "($header). The working corpus (\`$dir/corpus/TARGET\`) starts from"
    echo "\`tests/fuzz/seeds/TARGET\` and keeps what earlier runs on this machine found."
    echo
    echo "## All runs"
    echo
    echo "Every harness over every run so far (\`make fuzz FUZZ_TARGETS=TARGET\` runs one), against"
    echo "10 million executions each:"
    echo
    echo "| target | executions, all runs | runs | seconds | crashes | last run | 10 million |"
    echo "|---|---:|---:|---:|---:|---|---|"
    tail -n +2 "$totals" | while IFS=, read -r t runs execs secs crashes first last; do
        reached=$(awk -v n="$execs" 'BEGIN { print (n >= 10000000) ? "reached" : sprintf("**%.1f million short**", (10000000 - n) / 1e6) }')
        echo "| $t | $execs | $runs | $secs | $crashes | $last | $reached |"
    done
    echo
    echo "## What each harness checks"
    echo
    echo "Beyond the sanitizers:"
    echo
    echo "- **scene**: the input is written to a file and loaded as \`bentray render\` would: scene_load,"
    echo "  scene_validate, then one override through scene_set (the text of the last line starting with"
    echo "  \`;set \`, a comment to the loader, else the last line) and scene_validate again. Every refusal"
    echo "  must carry a non-empty, terminated message."
    echo "- **kiosk_config**: kiosk_config_load, then kiosk_config_check. Every refusal carries a"
    echo "  message; what the check accepts must be usable by the kiosk: the start scene is listed, the"
    echo "  knobs' and buttons' inputs exist, every hid input's report layout passes hid_layout_check,"
    echo "  every encoder's counts_per_detent passes quadrature_init and every button's debounce window"
    echo "  debounce_init. Relative paths resolve as from \`kiosk/\`, so the seeds' scenes are found."
    echo "- **dump**: dump_read; an accepted dump has sides and object count within the format's limits,"
    echo "  accounts for every byte of the file, and comes back bit for bit through dump_write and a second"
    echo "  dump_read; a refused one frees everything and says why."
    echo "- **hid**: a layout built from the input's first bytes goes to hid_layout_check (the same answer"
    echo "  with an error to fill and without; a refusal carries a message, ERROR_INPUT); layouts it accepts decode the rest of"
    echo "  the input as a report: the result code the header promises, the axis value as the bytes say, a"
    echo "  position within [0, 1] (never NaN), button bits as in the report and none beyond n_buttons;"
    echo "  powermate_decode on the same report; counter_delta against its definition (the shortest"
    echo "  difference modulo 2^bits, 0 for bits outside 1..32)."
    echo "- **gpio**: the input is a stream of (line, level, time step) events, times anywhere on the"
    echo "  64-bit clock, sometimes stepping back. Quadrature (1, 2 or 4 counts per detent): an edge emits"
    echo "  at most one detent, the total moves by exactly what is emitted, quarter steps stay within"
    echo "  +-(counts - 1), both lines at once is one invalid edge and nothing else. Debounce (edges and"
    echo "  polls): presses and releases alternate, older edges are rejected and counted, each change is"
    echo "  reported once and exactly when debounce.h says. event_merge of two streams built from the"
    echo "  events: never more than out_cap written, min(out_cap, events) returned, in time order, and"
    echo "  exactly the stable merge."
    echo "- **script**: the input is written to a file and read by script_load, as the kiosk does at start."
    echo "  Every refusal names the file; what is accepted can be replayed: at most SCRIPT_MAX_EVENTS"
    echo "  events, times finite, from 0 and never decreasing, counts within SCRIPT_MAX_COUNTS, known"
    echo "  actions; the player hands every event out exactly once, in order, however the clock advances."
    echo
    echo "## Reproducers kept"
    echo
    kept=0
    for f in tests/fuzz/crashes/*/*; do
        [ -f "$f" ] || continue
        case $f in *.txt) continue ;; esac
        kept=$((kept + 1))
        note=""
        [ -f "$f.txt" ] && note=": $(head -n 1 "$f.txt")"
        echo "- \`$f\` ($(wc -c < "$f" | tr -d ' ') bytes)$note"
    done
    if [ "$kept" = 0 ]; then
        echo "None: no harness has found a failure in the project's code that is kept for reproduction."
    else
        echo
        echo "Each is described in full in the \`.txt\` file next to it. They are not in the seed corpus:"
        echo "as long as the bug is there, every run would stop on them at once. Once fixed, run"
        echo "\`build/fuzz/fuzz_TARGET FILE\` on each and move it into \`tests/fuzz/seeds/TARGET/\`."
    fi
    echo
    echo "## Running one again"
    echo
    echo "\`make fuzz\` prints the reproducer of a failure (\`$dir/crashes/TARGET/...\`);"
    echo "\`$dir/fuzz_TARGET FILE\` runs that input alone, with the sanitizer's report and stack."
    echo "\`BT_FUZZ_TMPDIR\` sets where the harnesses write their input as a file (default \`\$TMPDIR\`"
    echo "or \`/tmp\`); the file is removed when the harness exits, and \`make fuzz\` removes what a"
    echo "crashed one leaves behind."
} > "$report.tmp"
mv "$report.tmp" "$report"
echo "wrote $report and $totals"
