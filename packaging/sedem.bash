# bash completion for sedem: commands, each command's options, scene files and run folders.
_sedem() {
  local cur prev words cword
  if declare -F _init_completion >/dev/null; then
    _init_completion || return
  else
    cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}
    words=("${COMP_WORDS[@]}") cword=$COMP_CWORD
  fi
  local commands="run batch render paraview reduce invert design bench"
  local command="" i
  for ((i = 1; i < cword; i++)); do
    case ${words[i]} in run|batch|render|paraview|reduce|invert|design|bench) command=${words[i]}; break ;; esac
  done
  if [[ -z $command ]]; then
    COMPREPLY=($(compgen -W "$commands --help --version" -- "$cur"))
    return
  fi
  local opts
  case $command in
    run) opts="--resume --out --overwrite --set --quiet -q --help -h" ;;
    batch) opts="--sweep --seeds --seed0 --out --set --jobs -j --overwrite --quiet -q --emit --gather
      --slurm-time --slurm-mem --slurm-cpus --slurm-partition --slurm-account --help -h" ;;
    render) opts="--out --partial --quiet -q --help -h" ;;
    paraview) opts="--pvpython --time --screenshot --quiet -q --help -h" ;;
    reduce) opts="--out --method --gs --mass-g --volume-ml --sheet --sieve --sieve-sheet
      --sieve-total-g --separating-sieve-mm --report --help -h" ;;
    invert) opts="--run --partial --test --scene --out --method --gs --mass-g --volume-ml --area-cm2
      --sheet --sieve --sieve-sheet --sieve-total-g --separating-sieve-mm
      --depth-cm --temperature-c --liquid-density --blank-g --pipette-ml --resolution --refine
      --replicas --coverage --seed --quiet -q --help -h" ;;
    design) opts="--test --readings --out --set --dem-count --sizes --quiet -q --help -h" ;;
    bench) opts="--help -h" ;;
  esac
  case $prev in
    --out|--resume|--gather) COMPREPLY=($(compgen -d -- "$cur")); return ;;
    --emit) COMPREPLY=($(compgen -W "slurm parallel" -- "$cur")); return ;;
    --method) COMPREPLY=($(compgen -W "d7928 d422" -- "$cur")); return ;;
    --test) COMPREPLY=($(compgen -W "hydrometer buoyancy pipette" -- "$cur")); return ;;
    --run) COMPREPLY=($(compgen -d -- "$cur")); return ;;
    --scene) COMPREPLY=($(compgen -f -X '!*.toml' -- "$cur") $(compgen -d -- "$cur")); return ;;
    --pvpython|--screenshot) COMPREPLY=($(compgen -f -- "$cur")); return ;;
    --sieve) COMPREPLY=($(compgen -f -- "$cur")); return ;;
    --report) COMPREPLY=($(compgen -f -X '!*.html' -- "$cur") $(compgen -d -- "$cur")); return ;;
    --set|--time|--sweep|--seeds|--seed0|--gs|--mass-g|--jobs|-j|--readings|--dem-count|--sizes) return ;;
    --sheet|--sieve-sheet|--sieve-total-g|--separating-sieve-mm) return ;;
    --slurm-time|--slurm-mem|--slurm-cpus|--slurm-partition|--slurm-account) return ;;
  esac
  if [[ $cur == -* ]]; then
    COMPREPLY=($(compgen -W "$opts" -- "$cur"))
    return
  fi
  case $command in
    run|batch|design) COMPREPLY=($(compgen -f -X '!*.toml' -- "$cur") $(compgen -d -- "$cur")) ;;
    render|paraview) COMPREPLY=($(compgen -d -- "$cur")) ;;
    reduce|invert) COMPREPLY=($(compgen -f -- "$cur")) ;;
    bench) COMPREPLY=($(compgen -W "engine accuracy speedup scale" -- "$cur")) ;;
  esac
}
complete -o filenames -F _sedem sedem
