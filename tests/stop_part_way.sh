# Sourced by the tests that resume an interrupted render (split_merge_test.sh, adaptive_test.sh).
# stop_part_way PT OUT RENDER-ARGS...: starts `PT render RENDER-ARGS... -o OUT` and sends it
# SIGTERM 1 s later. A signal before rendering begins (pt still starting or loading, on a busy
# machine) stops it with nothing written: then it tries again, signalling after 2 and 4 s.
# Returns pt's exit status (143 when stopped); the finished samples are in OUT's .partial.exr.
# meta FILE NAME: a metadata value of an EXR (of a partial, say).
meta() { /usr/bin/python3 -c "import OpenImageIO as o,sys; s=o.ImageInput.open(sys.argv[1]).spec(); print(s.getattribute(sys.argv[2]))" "$1" "$2"; }

stop_part_way() {
  local pt=$1 out=$2 delay pid status
  shift 2
  for delay in 1 2 4; do
    "$pt" render "$@" -o "$out" >/dev/null 2>&1 &
    pid=$!
    sleep $delay
    kill -TERM "$pid" 2>/dev/null
    wait "$pid"
    status=$?
    [[ $status -eq 143 && ! -f ${out%.exr}.partial.exr ]] || break
  done
  return $status
}
