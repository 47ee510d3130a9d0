#pragma once
// Checkpoints of a distributed run (issue 20), written in parallel: each rank writes its piece,
// checkpoint_NNNNNN_pK.bin (its owned bodies' state and the active contacts it answers for, in
// global ids), then rank 0 the manifest under the checkpoint's own name, checkpoint_NNNNNN.bin
// (header, step, ledger, drivers, output progress, and each piece's name, size and checksum),
// last: a run that stops before it keeps its previous checkpoint whole. `--resume` of a manifest
// on ranks that integrate their own bodies (a contact stage): each rank reads a share of the
// pieces (k = rank, rank + ranks, ...), which the first step sends to the bodies' owners
// (sim/rank_landing.hpp); else every piece, laid out as one process's checkpoint holds it. A
// run continues on any rank count, or one process, bit for bit.
#include <string>

#include "sim/checkpoint.hpp"

namespace polydem {

// A collective of every rank of `sim`'s link; when one rank cannot write, every rank throws
// RunError with its message.
void write_checkpoint_pieces(const std::string& path, const Simulation& sim, const OutputProgress& progress);

// Whether a checkpoint file's bytes are a manifest.
bool is_checkpoint_manifest(const std::string& bytes);
// A manifest's body order (checkpoint_body_order).
std::vector<std::uint32_t> manifest_body_order(const std::string& path, std::size_t bodies);

// Restores the state of the manifest `path` (its `bytes`) and its pieces; throws InputError
// naming the file and the piece when one is missing, damaged or of another checkpoint (on
// every rank, whichever read it: a collective on ranks).
void read_checkpoint_pieces(const std::string& path, const std::string& bytes, Simulation& sim,
                            OutputProgress& progress, bool force);

}  // namespace polydem
