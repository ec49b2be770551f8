# bash completion for bentray (installed by `make install` into share/bash-completion/completions)
_bentray()
{
    local cur prev cmd
    cur=${COMP_WORDS[COMP_CWORD]}
    prev=${COMP_WORDS[COMP_CWORD-1]}
    cmd=${COMP_WORDS[1]}
    if [ "$COMP_CWORD" -eq 1 ]; then
        COMPREPLY=($(compgen -W "render animate trace info compare error bench kiosk --version --help" -- "$cur"))
        return
    fi
    case $prev in
        --scene) COMPREPLY=($(compgen -f -X '!*.scene' -- "$cur") $(compgen -d -- "$cur")); return ;;
        --config) COMPREPLY=($(compgen -f -X '!*.conf' -- "$cur") $(compgen -d -- "$cur")); return ;;
        --out | --dump | --shader-dir | --video) COMPREPLY=($(compgen -f -- "$cur")); return ;;
        --backend) COMPREPLY=($(compgen -W "egl osmesa auto$([ "$cmd" = info ] && echo ' all')" -- "$cur")); return ;;
        --engine) COMPREPLY=($(compgen -W "gpu cpu" -- "$cur")); return ;;
        --precision) COMPREPLY=($(compgen -W "fp32 fp16 auto" -- "$cur")); return ;;
        --display) COMPREPLY=($(compgen -W "auto kms x11 headless" -- "$cur")); return ;;
        --depth) COMPREPLY=($(compgen -W "8 16" -- "$cur")); return ;;
        --compression) COMPREPLY=($(compgen -W "fast small" -- "$cur")); return ;;
        --size | --samples | --set | --set-range | --frames | --orbit | --fps | --rtol | --threads | --pixel | \
        --runs | --only) return ;;
    esac
    local common="--scene --size --samples --set --engine --backend --precision --no-mrt --shader-dir --rtol --threads --help"
    local opts
    case $cmd in
        render) opts="$common --out --depth --compression --dump --force --progress --quiet" ;;
        animate) opts="$common --frames --set-range --orbit --orbit-axis --out --force --video --fps --quiet" ;;
        trace) opts="--scene --pixel --size --set --engine --backend --precision --no-mrt --shader-dir --rtol --help" ;;
        error) opts="$common --json --check" ;;
        bench) opts="--out --force --runs --size --only --kiosk --config --quick --backend --help" ;;
        kiosk) opts="--config --display --backend --out --frames --force --stats --check-inputs --help" ;;
        compare) [[ $cur == -* ]] && COMPREPLY=($(compgen -W "--json --help" -- "$cur")) || COMPREPLY=($(compgen -f -- "$cur")); return ;;
        info) opts="--backend --shader-dir --shader --scene --set --no-mrt --help" ;;
        *) opts="--help" ;;
    esac
    COMPREPLY=($(compgen -W "$opts" -- "$cur"))
}
complete -F _bentray bentray
