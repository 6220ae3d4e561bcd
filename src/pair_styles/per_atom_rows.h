// SPDX-License-Identifier: GPL-2.0-or-later
// tdem: one row of doubles per atom that grows with the atom arrays, migrates with its atom and
// goes to restart files - the per-atom callbacks of a fix, written once for every tdem fix that
// keeps per-atom state (fix tdem/wall/gran's contact history, fix tdem/grate's contact slots, fix
// tdem/mixing/depth's trajectory state, fix tdem/integrate's histories), in LAMMPS and LIGGGHTS.
//
//   class FixX : public tdem::host::PerAtomRows<Fix> { ... rows_init(width, "x:rows") ... }
//
// The fix calls rows_init() in its constructor before atom->add_callback(), uses rows_[i][0 ..
// width_), and overrides a callback only where its rows need more (a marker in set_arrays, a
// restart head). Restart record per atom: [length, head, row] (pack_row; a record of another
// length or head is read as a zero row). Templated on the engine's Fix, so
// this header includes no engine header; the engine's atom.h and memory.h are needed where it is
// instantiated.
#pragma once

namespace tdem {
namespace host {

// The record of the nth per-atom restart fix of atom i among the extra values of a restart file
// (atom->extra[i]): rec[0] is its length including rec[0].
inline const double* restart_record(double* const* extra, int i, int nth) {
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[i][m]);
  return &extra[i][m];
}

template <class FixBase>
class PerAtomRows : public FixBase {
 public:
  using FixBase::FixBase;
  ~PerAtomRows() override { this->memory->destroy(rows_); }

  void grow_arrays(int n) override {
    if (n <= nmax_rows_) return;
    this->memory->grow(rows_, n, width_, rows_name_);
    for (int i = nmax_rows_; i < n; i++)
      for (int m = 0; m < width_; m++) rows_[i][m] = 0.0;
    nmax_rows_ = n;
    if (this->peratom_flag) this->array_atom = rows_;
  }
  void copy_arrays(int i, int j, int /*delflag*/) override {
    for (int m = 0; m < width_; m++) rows_[j][m] = rows_[i][m];
  }
  void set_arrays(int i) override {
    for (int m = 0; m < width_; m++) rows_[i][m] = 0.0;
  }
  int pack_exchange(int i, double* buf) override {
    for (int m = 0; m < width_; m++) buf[m] = rows_[i][m];
    return width_;
  }
  int unpack_exchange(int nlocal, double* buf) override {
    for (int m = 0; m < width_; m++) rows_[nlocal][m] = buf[m];
    return width_;
  }
  int pack_restart(int i, double* buf) override { return pack_row(i, buf, nullptr); }
  void unpack_restart(int nlocal, int nth) override { unpack_row(nlocal, nth, nullptr); }
  int size_restart(int /*nlocal*/) override { return 1 + restart_head_ + width_; }
  int maxsize_restart() override { return 1 + restart_head_ + width_; }

 protected:
  double** rows_ = nullptr;  // [atom][0 .. width_)
  int width_ = 0;
  int nmax_rows_ = 0;  // rows allocated
  const char* rows_name_ = "tdem:rows";

  void rows_init(int width, const char* name) {
    width_ = width;
    rows_name_ = name;
  }
  double rows_memory() const { return static_cast<double>(nmax_rows_) * width_ * sizeof(double); }

  // Restart record [1 + restart_head_ + width_, head[0 .. restart_head_), row of atom i]; the head
  // (e.g. the layout the row was written with) is checked when read.
  int restart_head_ = 0;
  int pack_row(int i, double* buf, const double* head) const {
    int n = 0;
    buf[n++] = 1 + restart_head_ + width_;
    for (int k = 0; k < restart_head_; k++) buf[n++] = head[k];
    for (int m = 0; m < width_; m++) buf[n++] = rows_[i][m];
    return n;
  }
  // The row of a record written by pack_row with the same head and length; else a zero row and false.
  bool unpack_row(int nlocal, int nth, const double* head) {
    const double* rec = restart_record(this->atom->extra, nlocal, nth);
    bool same = static_cast<int>(rec[0]) == 1 + restart_head_ + width_;
    for (int k = 0; same && k < restart_head_; k++) same = rec[1 + k] == head[k];
    for (int m = 0; m < width_; m++) rows_[nlocal][m] = same ? rec[1 + restart_head_ + m] : 0.0;
    return same;
  }
};

}  // namespace host
}  // namespace tdem
