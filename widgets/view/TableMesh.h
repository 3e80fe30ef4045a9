#pragma once
// The static geometry of a table as one triangle list: cloth, cushions extruded along their real
// profile (nose at Table::cushionHeight, the rubber sloping back under the nose, the jaw tips rounded
// as in the Table's geometry), the wooden rails with their sights, and a pocket pit at every pocket
// circle. Built on the CPU once per table; the renderer uploads it. No GL here.

#include "Table.h"

#include <QRectF>
#include <QVector3D>

#include <vector>

namespace cuelab {

// What the table shader does with a fragment. Cloth, cushions and rails are cut away inside the
// pocket circles (the shader discards them there), which opens the pits below.
enum class SurfaceMaterial : int {
    Cloth = 0,
    Cushion = 1,
    Wood = 2,
    PocketPit = 3,
    Sight = 4,   // inlaid diamonds and the spots on the cloth: never cut
    Solid = 5,   // anything else lit plainly (the cue stick)
};

struct MeshVertex {
    QVector3D position;  // m, table frame
    QVector3D normal;    // unit
    QVector3D colour;    // linear RGB
    float material = 0;  // a SurfaceMaterial, as the shader reads it
};

// Dimensions of the parts that the simulation does not need (everything behind the cushion nose).
struct TableDimensions {
    double cushionDepth = 0.05;  // m, from the nose line back to the rail
    double railWidth = 0.13;     // m, the wood beyond the cushion
    double railTop = 0.0;        // m, height of the rail's top surface above the cloth
    double skirtDepth = 0.20;    // m, how far the wooden sides reach below the cloth
    double pitDepth = 0.15;      // m, depth of a pocket pit below the cloth
};

TableDimensions tableDimensions(const Table& table);

// The table with its rails, in the table frame (m).
QRectF tableExtent(const Table& table);

// Cloth colour of a table kind (green for pool and snooker, blue for carom).
QVector3D clothColour(TableKind kind);

std::vector<MeshVertex> buildTableMesh(const Table& table);

// Reorders the triangles so that those a pocket circle may cut (cloth, cushion or wood within reach of
// a pocket) come last, and returns how many vertices come before them. The renderer draws the first
// part with a shader that never discards, which lets a software rasteriser keep its fast paths.
std::size_t partitionByPocketCut(const Table& table, std::vector<MeshVertex>& mesh);

}  // namespace cuelab
