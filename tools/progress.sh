# SPDX-License-Identifier: GPL-2.0-or-later
# Progress lines with an estimate of the remaining time, for the sh scripts of validation/ and
# bench/ (sourced: `. "$root/tools/progress.sh"`). POSIX sh.
#
#   progress_init "NAME:WEIGHT NAME:WEIGHT ..."   the stages and their expected relative cost
#   progress_done NAME                            after stage NAME: prints
#       [progress] k/N NAME done after S s; elapsed E s, about R s to go
# R = E x (weight of the stages left) / (weight of the stages done): a first stage that is slower
# than its weight says makes the estimate of the rest larger.
progress_init() {
  _pg_stages=$1
  _pg_t0=$(date +%s)
  _pg_last=$_pg_t0
  _pg_k=0
  _pg_n=0
  _pg_wall=0
  for _pg_s in $_pg_stages; do
    _pg_n=$((_pg_n + 1))
    _pg_wall=$((_pg_wall + ${_pg_s#*:}))
  done
  _pg_wdone=0
}

progress_done() {
  _pg_now=$(date +%s)
  _pg_w=1
  for _pg_s in $_pg_stages; do
    [ "${_pg_s%%:*}" = "$1" ] && _pg_w=${_pg_s#*:}
  done
  _pg_k=$((_pg_k + 1))
  _pg_wdone=$((_pg_wdone + _pg_w))
  _pg_el=$((_pg_now - _pg_t0))
  _pg_left=$((_pg_wall - _pg_wdone))
  [ "$_pg_left" -lt 0 ] && _pg_left=0
  _pg_rem=$(( _pg_wdone > 0 ? _pg_el * _pg_left / _pg_wdone : 0 ))
  echo "[progress] $_pg_k/$_pg_n $1 done after $((_pg_now - _pg_last)) s; elapsed $_pg_el s, about $_pg_rem s to go"
  _pg_last=$_pg_now
}
