// The per-piece arithmetic of regular tracking (media/exact_tracking.h): the running optical depth
// over a ray's exact-extinction pieces (media/medium.h, EXACT EXTINCTION), and the search for the
// piece where the hero channel's depth reaches a target. Two visitor classes, so that a medium that
// walks its own pieces (volumes/grid_medium.cpp) can take them as a template argument and inline
// them into its walk: no indirect call per piece (the walk visits ~8 cells per delta-tracking
// lookup, and a FunctionRef per cell cost as much as the cell's cubic). Medium's default
// exactOpticalDepth() / exactDepthCrossing() run the same visitors through extinctionPieces(), so
// every medium computes the same sums in the same order.
//
// PIECES. The visitors take any piece type P with members scale (Vec3d) and free functions found
// by argument-dependent lookup: wholePieceIntegral(p), the cubic's integral over all of the piece,
// and cubicPiece(p), the piece as an ExtinctionPiece (its cubic). ExtinctionPiece is one; a medium
// may hand its own, whose integral it knows without the cubic and whose cubic it computes only when
// asked (volumes/grid_medium.cpp): the search asks only at the piece where the flight stops.
#pragma once

#include <algorithm>
#include <cmath>

#include "media/medium.h"

namespace fluence::media {

// The cubic and its integral over [0, s] (OPTICAL DEPTH of media/exact_tracking.h), before the
// channel's scale.
inline double polynomialAt(const ExtinctionPiece& piece, double s) {
    const double* k = piece.polynomial;
    return ((k[3] * s + k[2]) * s + k[1]) * s + k[0];
}
inline double integralAt(const ExtinctionPiece& piece, double s) {
    const double* k = piece.polynomial;
    return (((k[3] * 0.25 * s + k[2] * (1.0 / 3.0)) * s + k[1] * 0.5) * s + k[0]) * s;
}

// The integral over all of the piece, before the channel's scale: infinite for an unbounded piece
// (an infinite homogeneous medium's, constant).
inline double wholePieceIntegral(const ExtinctionPiece& piece) {
    const double length = piece.tMax - piece.tMin;
    return std::isfinite(length) ? integralAt(piece, length) : INFINITY;
}
inline const ExtinctionPiece& cubicPiece(const ExtinctionPiece& piece) { return piece; }

// tau_c over all of an unbounded piece: infinitely deep in every channel it attenuates and
// transparent in the others.
Vec3d unboundedPieceDepth(const ExtinctionPiece& piece);

// tau_c over all of the piece, given `total`, its wholePieceIntegral.
template <class Piece>
Vec3d wholePieceDepth(const Piece& piece, double total) {
    return std::isfinite(total) ? piece.scale * total : unboundedPieceDepth(cubicPiece(piece));
}

// The s in [0, length] where the piece's integral reaches `remaining` (0 < remaining <= its
// integral `total` over the piece): Newton's method on the monotone integral, kept inside a
// shrinking bracket by bisection, to double precision.
double invertIntegral(const ExtinctionPiece& piece, double length, double total, double remaining);

// Sums tau_c over every piece it is given (exactOpticalDepth()).
struct OpticalDepthSum {
    OpticalDepth depth;
    template <class Piece>
    bool operator()(const Piece& piece) {
        ++depth.pieces;
        depth.tau += wholePieceDepth(piece, wholePieceIntegral(piece));
        return true;
    }
};

// Runs tau_c piece by piece until the hero's reaches `target`, then stops there (exactDepthCrossing()):
// the crossing's t, its tau_c and sigmaT_c; tStop < 0 if the pieces end first.
struct DepthCrossingSearch {
    int hero = 0;
    double target = 0.0;
    DepthCrossing crossing;
    template <class Piece>
    bool operator()(const Piece& piece) {
        ++crossing.pieces;
        const double scale = piece.scale[hero], total = wholePieceIntegral(piece);
        if (!(scale > 0.0) || !(total > 0.0) || crossing.tau[hero] + scale * total < target) {
            crossing.tau += wholePieceDepth(piece, total);
            return true;
        }
        stop(cubicPiece(piece), total);
        return false;
    }
    // The crossing inside `piece`, whose integral `total` takes the hero's depth to the target.
    void stop(const ExtinctionPiece& piece, double total);
};

}  // namespace fluence::media
