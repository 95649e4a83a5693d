// Exact area rasterization of geodesic triangles onto the equirectangular grid.
//
// Method. In Lambert's cylindrical equal-area coordinates (phi, u) with u = -cos(theta) = -z,
// the sphere's area element is exactly du dphi and every grid cell is the rectangle
// [2 pi i/N, 2 pi (i+1)/N] x [u_j, u_{j+1}], u_j = -cos(pi j/N). By Green's theorem, for a region R
// whose closure avoids the south pole,
//   area(R intersect cell(j, i)) = oint_{boundary of R, within column i} H_j(u) dphi,
//   H_j(u) = clamp(u, u_j, u_{j+1}) - u_j
// (the boundary oriented counter-clockwise seen from outside; boundary pieces on the north pole,
// u = -1, contribute nothing because H_j(-1) = 0, and meridian pieces have dphi = 0). A great
// circle arc with unit normal n (n_z != 0) is a graph u(phi) = s q/sqrt(n_z^2 + q^2),
// q = n_x cos phi + n_y sin phi, s = sign(n_z), with the closed-form antiderivative
//   U(phi) = s atan2(n_x sin phi - n_y cos phi, sqrt(n_z^2 + q^2)),
// and it crosses latitude u_k where q = n_z u_k / sin(theta_k). So every edge contributes, per
// column it sweeps and per row, a closed-form integral: no numerical quadrature, no polygon
// clipping, exact up to round-off.
//
// Poles. If the triangle contains the north pole, rows above its boundary in each column are
// fully covered (their share is the net azimuth swept in that column). If its closure contains
// the south pole we use H_j(u) - (u_{j+1} - u_j), the same identity measured from the south
// pole, which subtracts the net swept azimuth times the row height. Both are recorded as
// per-column "all rows north/south of row k" markers and expanded by prefix sums at the end, so
// a triangle costs time proportional to the cells its boundary touches.
//
// Seam. Azimuths are unwrapped along each edge (an edge sweeps less than pi), columns taken
// modulo N.
//
// Normalization. Each triangle's pieces are scaled so that they sum to its original area (the
// computed spherical area of the pieces, not a separate formula, is the denominator), so the
// grid conserves area to round-off whatever the round-off in the pieces. Round-off can make a
// piece of a triangle that is many orders of magnitude smaller than a cell slightly wrong or
// negative (U is evaluated in absolute terms, error ~1e-16 per piece); negative pieces are
// clamped to zero before normalizing. Triangles entirely inside one cell (the common case) take a
// fast path that needs no piece computation at all and is exact.
#include "SphericalAreaGrid.h"

#include "ParallelFor.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <sstream>

namespace mobius
{
namespace
{
using Vec3 = Eigen::Vector3d;

/// Row and column boundaries of the grid, and the per-row quantities every triangle needs.
struct GridGeometry
{
  int N = 0;
  double ColumnWidth = 0.0;        // h = 2 pi/N
  std::vector<double> RowU;        // u_j = -cos(pi j/N), j = 0..N
  std::vector<double> RowSine;     // sin(pi j/N), j = 0..N
  std::vector<double> RowHeight;   // u_{j+1} - u_j, accurate near the poles
  std::vector<double> ColumnCos;   // cos(2 pi i/N), i = 0..N-1
  std::vector<double> ColumnSin;   // sin(2 pi i/N)

  explicit GridGeometry(int n)
    : N(n)
    , ColumnWidth(2.0 * M_PI / n)
  {
    RowU.resize(n + 1);
    RowSine.resize(n + 1);
    RowHeight.resize(n);
    for (int j = 0; j <= n; ++j)
    {
      RowU[j] = -std::cos(M_PI * j / n);
      RowSine[j] = std::sin(M_PI * j / n);
    }
    RowU[0] = -1.0;
    RowU[n] = 1.0;
    for (int j = 0; j < n; ++j)
    {
      // cos a - cos b = 2 sin((a+b)/2) sin((b-a)/2)
      RowHeight[j] = 2.0 * std::sin(M_PI * (j + 0.5) / n) * std::sin(M_PI / (2.0 * n));
    }
    ColumnCos.resize(n);
    ColumnSin.resize(n);
    for (int i = 0; i < n; ++i)
    {
      ColumnCos[i] = std::cos(ColumnWidth * i);
      ColumnSin[i] = std::sin(ColumnWidth * i);
    }
  }

  int Row(double u) const
  {
    int j = static_cast<int>(std::floor(std::acos(std::clamp(-u, -1.0, 1.0)) * N / M_PI));
    j = std::clamp(j, 0, N - 1);
    while (j > 0 && u < RowU[j])
    {
      --j;
    }
    while (j < N - 1 && u >= RowU[j + 1])
    {
      ++j;
    }
    return j;
  }

  int Column(double phi) const
  {
    return std::clamp(static_cast<int>(std::floor(phi / ColumnWidth)), 0, N - 1);
  }

  int Wrap(long column) const
  {
    const long n = N;
    return static_cast<int>(((column % n) + n) % n);
  }
};

struct Vertex
{
  Vec3 X;       // unit vector
  double Phi;   // [0, 2 pi)
  int Row;
  int Column;
};

/// One great-circle edge, with u(phi) and its antiderivative U(phi) in closed form.
struct Edge
{
  Vec3 Normal;   // unit normal of the edge's plane, n_z != 0
  double Sign;   // sign(n_z)
  double Rho;    // sqrt(n_x^2 + n_y^2)
  mutable double Phi0 = 0.0;  // atan2(n_y, n_x): u is extremal at Phi0 + k pi
  mutable bool HasPhi0 = false; // computed on first use (saves an atan2 for most edges)

  double GetPhi0() const
  {
    if (!HasPhi0)
    {
      Phi0 = std::atan2(Normal.y(), Normal.x());
      HasPhi0 = true;
    }
    return Phi0;
  }
  /// U and u at azimuth phi; p = rho sin(phi - Phi0) has the sign of -du/dphi * Sign.
  double UAt(double cosPhi, double sinPhi, double& u, double& p) const
  {
    const double q = Normal.x() * cosPhi + Normal.y() * sinPhi;
    p = Normal.x() * sinPhi - Normal.y() * cosPhi;
    const double r = std::sqrt(Normal.z() * Normal.z() + q * q);
    u = Sign * q / r;
    return Sign * std::atan2(p, r);
  }
  /// U at a point x of the great circle; p is returned up to a positive factor.
  double UAtPoint(const Vec3& x, double& p) const
  {
    p = Normal.x() * x.y() - Normal.y() * x.x();
    return Sign * std::atan2(p, std::abs(Normal.z()));
  }
};

/// A part of an edge within one column on which u is monotone.
struct Piece
{
  long Column; // unwrapped column index
  int EdgeIndex;
  double Sign; // +1: the boundary runs toward increasing phi here, -1: decreasing
  double S, T; // azimuth interval, S < T
  double US, UT; // u at S and T
  double AntiS, AntiT; // U at S and T
  int RowS = 0, RowT = 0; // grid rows of US and UT
};

/// Per-thread accumulation: explicit cell areas plus "all rows north of k" and
/// "all rows south of k" markers (values in radians of azimuth, multiplied by row heights later).
struct Accumulator
{
  std::vector<double> Cells;       // N*N
  std::vector<double> NorthMarker; // (N+1)*N: rows j < k get RowHeight[j] * marker[k]
  std::vector<double> SouthMarker; // N*N: rows j > k get RowHeight[j] * marker[k]

  explicit Accumulator(int n)
    : Cells(size_t(n) * n, 0.0)
    , NorthMarker(size_t(n + 1) * n, 0.0)
    , SouthMarker(size_t(n) * n, 0.0)
  {
  }

  void Clear()
  {
    std::fill(this->Cells.begin(), this->Cells.end(), 0.0);
    std::fill(this->NorthMarker.begin(), this->NorthMarker.end(), 0.0);
    std::fill(this->SouthMarker.begin(), this->SouthMarker.end(), 0.0);
  }

  void Add(const Accumulator& other)
  {
    for (size_t k = 0; k < this->Cells.size(); ++k)
    {
      this->Cells[k] += other.Cells[k];
      this->SouthMarker[k] += other.SouthMarker[k];
    }
    for (size_t k = 0; k < this->NorthMarker.size(); ++k)
    {
      this->NorthMarker[k] += other.NorthMarker[k];
    }
  }
};

// The triangles are rasterized in at most this many parts of at least this many triangles
// (fewer make the parts' merging cost more than it saves).
constexpr int MaximumRasterParts = 8;
constexpr Eigen::Index TrianglesPerRasterPart = 4096;

class TriangleRasterizer
{
public:
  TriangleRasterizer(const GridGeometry& grid, Accumulator& accumulator)
    : Grid(grid)
    , Out(accumulator)
  {
  }

  void Add(const Vertex& a, const Vertex& b, const Vertex& c, double area)
  {
    if (area == 0.0)
    {
      return;
    }
    if (a.Row == b.Row && a.Row == c.Row && a.Column == b.Column && a.Column == c.Column &&
      this->StaysInRow(a.X, b.X, a.Row) && this->StaysInRow(b.X, c.X, a.Row) &&
      this->StaysInRow(c.X, a.X, a.Row))
    {
      this->Out.Cells[size_t(a.Row) * this->Grid.N + a.Column] += area;
      return;
    }
    if (!this->AddGeneral(a, b, c, area))
    {
      this->AddToCentroidCell(a, b, c, area);
    }
  }

private:
  /// Does the geodesic arc PQ stay within the latitude band of row j? (Its azimuth range is
  /// within one column already, and column wedges are convex.) The arc leaves the band only if
  /// it contains the northernmost or southernmost point of its great circle and that point is
  /// outside the band.
  bool StaysInRow(const Vec3& p, const Vec3& q, int row) const
  {
    const Vec3 m = p.cross(q);
    const double length = m.norm();
    if (length == 0.0)
    {
      return true;
    }
    const Vec3 n = m / length;
    const Vec3 top(-n.z() * n.x(), -n.z() * n.y(), 1.0 - n.z() * n.z()); // northernmost direction
    const double zExtreme = std::sqrt(std::max(0.0, 1.0 - n.z() * n.z()));
    if (p.cross(top).dot(m) >= 0.0 && top.cross(q).dot(m) >= 0.0 &&
      -zExtreme < this->Grid.RowU[row])
    {
      return false;
    }
    const Vec3 bottom = -top;
    if (p.cross(bottom).dot(m) >= 0.0 && bottom.cross(q).dot(m) >= 0.0 &&
      zExtreme > this->Grid.RowU[row + 1])
    {
      return false;
    }
    return true;
  }

  void AddToCentroidCell(const Vertex& a, const Vertex& b, const Vertex& c, double area)
  {
    Vec3 centroid = a.X + b.X + c.X;
    if (centroid.squaredNorm() == 0.0)
    {
      centroid = a.X;
    }
    centroid.normalize();
    double phi = std::atan2(centroid.y(), centroid.x());
    if (phi < 0.0)
    {
      phi += 2.0 * M_PI;
    }
    const int row = this->Grid.Row(-centroid.z());
    const int column = this->Grid.Column(phi);
    this->Out.Cells[size_t(row) * this->Grid.N + column] += area;
  }

  bool AddGeneral(const Vertex& a, const Vertex& b, const Vertex& c, double area)
  {
    // det(a, b, c) written with edge vectors: a.(b x c) cancels catastrophically for tiny
    // triangles on the unit sphere and can get the orientation wrong.
    const double det = a.X.dot((b.X - a.X).cross(c.X - a.X));
    if (!(det != 0.0))
    {
      return false;
    }
    const double orientation = det > 0.0 ? 1.0 : -1.0;
    // Pole containment (closure) from the signs of det(a, b, pole) etc.
    const double zab = a.X.cross(b.X).z() * orientation;
    const double zbc = b.X.cross(c.X).z() * orientation;
    const double zca = c.X.cross(a.X).z() * orientation;
    const bool containsNorth = zab >= 0.0 && zbc >= 0.0 && zca >= 0.0;
    const bool containsSouth = zab <= 0.0 && zbc <= 0.0 && zca <= 0.0;
    if (containsNorth && containsSouth)
    {
      return false; // degenerate: e.g. antipodal vertices
    }

    this->Edges.clear();
    this->Pieces.clear();
    this->RowMin = std::min({ a.Row, b.Row, c.Row });
    this->RowMax = std::max({ a.Row, b.Row, c.Row });
    this->AddEdgePieces(a, b);
    this->AddEdgePieces(b, c);
    this->AddEdgePieces(c, a);
    if (this->Pieces.empty())
    {
      return false;
    }

    // Local buffer over the rows and (unwrapped) columns the boundary touches.
    long columnMin = this->Pieces.front().Column, columnMax = columnMin;
    for (const Piece& piece : this->Pieces)
    {
      columnMin = std::min(columnMin, piece.Column);
      columnMax = std::max(columnMax, piece.Column);
    }
    const int n = this->Grid.N;
    const bool wrapped = columnMax - columnMin + 1 > n;
    const int width = wrapped ? n : static_cast<int>(columnMax - columnMin + 1);
    const int rows = this->RowMax - this->RowMin + 1;
    this->Local.assign(size_t(rows) * width, 0.0);
    this->Swept.assign(width, 0.0);
    auto localColumn = [&](long column) {
      return wrapped ? this->Grid.Wrap(column) : static_cast<int>(column - columnMin);
    };
    for (const Piece& piece : this->Pieces)
    {
      this->IntegratePiece(piece, localColumn(piece.Column), width);
    }

    // Pole corrections and the triangle's total (signed by orientation) spherical area.
    double total = 0.0;
    if (containsSouth)
    {
      for (int k = 0; k < width; ++k)
      {
        for (int r = 0; r < rows; ++r)
        {
          this->Local[size_t(r) * width + k] -= this->Swept[k] * this->Grid.RowHeight[this->RowMin + r];
        }
      }
    }
    for (double& value : this->Local)
    {
      value = std::max(0.0, value * orientation);
      total += value;
    }
    // Rows north of RowMin (north pole inside) / south of RowMax (south pole inside) are covered
    // by the net azimuth swept in their column.
    const double northRows = this->Grid.RowU[this->RowMin] + 1.0;
    const double southRows = 1.0 - this->Grid.RowU[this->RowMax + 1];
    for (int k = 0; k < width; ++k)
    {
      if (containsNorth)
      {
        total += orientation * this->Swept[k] * northRows;
      }
      else if (containsSouth)
      {
        total -= orientation * this->Swept[k] * southRows;
      }
    }
    if (!(total > 0.0) || !std::isfinite(total))
    {
      return false;
    }

    const double scale = area / total;
    for (int k = 0; k < width; ++k)
    {
      const int column = wrapped ? k : this->Grid.Wrap(columnMin + k);
      for (int r = 0; r < rows; ++r)
      {
        const double value = this->Local[size_t(r) * width + k];
        if (value != 0.0)
        {
          this->Out.Cells[size_t(this->RowMin + r) * n + column] += scale * value;
        }
      }
      if (containsNorth)
      {
        this->Out.NorthMarker[size_t(this->RowMin) * n + column] +=
          scale * orientation * this->Swept[k];
      }
      else if (containsSouth)
      {
        this->Out.SouthMarker[size_t(this->RowMax) * n + column] -=
          scale * orientation * this->Swept[k];
      }
    }
    return true;
  }

  /// Splits the arc from -> to into column pieces on which u is monotone.
  void AddEdgePieces(const Vertex& from, const Vertex& to)
  {
    const Vec3 m = from.X.cross(to.X);
    const double length = m.norm();
    if (length == 0.0 || m.z() == 0.0)
    {
      return; // a point, a meridian arc or an arc through a pole: no azimuth-weighted area
    }
    Edge edge;
    edge.Normal = m / length;
    edge.Sign = edge.Normal.z() > 0.0 ? 1.0 : -1.0;
    edge.Rho = std::sqrt(edge.Normal.x() * edge.Normal.x() + edge.Normal.y() * edge.Normal.y());
    // Azimuth increases along the arc iff n_z > 0; an arc not through a pole sweeps < pi.
    double sweep = to.Phi - from.Phi;
    if (sweep > M_PI)
    {
      sweep -= 2.0 * M_PI;
    }
    else if (sweep < -M_PI)
    {
      sweep += 2.0 * M_PI;
    }
    if (edge.Sign > 0.0 && sweep < 0.0)
    {
      sweep += 2.0 * M_PI;
    }
    else if (edge.Sign < 0.0 && sweep > 0.0)
    {
      sweep -= 2.0 * M_PI;
    }
    if (sweep == 0.0)
    {
      return;
    }
    const int edgeIndex = static_cast<int>(this->Edges.size());
    this->Edges.push_back(edge);

    const Vertex& west = sweep > 0.0 ? from : to;
    const Vertex& east = sweep > 0.0 ? to : from;
    const double sign = sweep > 0.0 ? 1.0 : -1.0;
    const double start = west.Phi;
    const double end = west.Phi + std::abs(sweep);
    const double h = this->Grid.ColumnWidth;
    long column = west.Column;
    double pS, pT;
    double s = start, us = -west.X.z(), antiS = edge.UAtPoint(west.X, pS);
    int rowS = west.Row, rowT;
    while (true)
    {
      const double boundary = (column + 1) * h;
      double t, ut, antiT;
      const bool last = end <= boundary;
      if (last)
      {
        t = end;
        ut = -east.X.z();
        antiT = edge.UAtPoint(east.X, pT);
        rowT = east.Row;
      }
      else
      {
        t = boundary;
        const int wrappedBoundary = this->Grid.Wrap(column + 1);
        antiT = edge.UAt(
          this->Grid.ColumnCos[wrappedBoundary], this->Grid.ColumnSin[wrappedBoundary], ut, pT);
        rowT = this->Grid.Row(ut);
      }
      if (t > s)
      {
        // u is extremal where p = rho sin(phi - Phi0) changes sign (phi = Phi0 + k pi).
        if ((pS > 0.0 && pT < 0.0) || (pS < 0.0 && pT > 0.0))
        {
          const double phi0 = edge.GetPhi0();
          const double k = std::ceil((s - phi0) / M_PI);
          const double extreme = std::clamp(phi0 + k * M_PI, s, t);
          const double uExtreme =
            edge.Sign * edge.Rho * ((static_cast<long>(k) % 2 == 0) ? 1.0 : -1.0);
          const int rowExtreme = this->Grid.Row(uExtreme);
          this->PushPiece(
            { column, edgeIndex, sign, s, extreme, us, uExtreme, antiS, 0.0, rowS, rowExtreme });
          this->PushPiece(
            { column, edgeIndex, sign, extreme, t, uExtreme, ut, 0.0, antiT, rowExtreme, rowT });
        }
        else
        {
          this->PushPiece({ column, edgeIndex, sign, s, t, us, ut, antiS, antiT, rowS, rowT });
        }
      }
      if (last)
      {
        break;
      }
      s = t;
      us = ut;
      antiS = antiT;
      pS = pT;
      rowS = rowT;
      ++column;
    }
  }

  void PushPiece(const Piece& piece)
  {
    this->RowMin = std::min({ this->RowMin, piece.RowS, piece.RowT });
    this->RowMax = std::max({ this->RowMax, piece.RowS, piece.RowT });
    this->Pieces.push_back(piece);
  }

  /// Adds sign * int_S^T H_j(u(phi)) dphi to every row j in [RowMin, RowMax] of the column.
  void IntegratePiece(const Piece& piece, int column, int width)
  {
    const Edge& edge = this->Edges[piece.EdgeIndex];
    const GridGeometry& grid = this->Grid;
    double* local = this->Local.data() + column;
    auto at = [&](int row) -> double& { return local[size_t(row - this->RowMin) * width]; };
    const double length = piece.T - piece.S;
    this->Swept[column] += piece.Sign * length;

    const int rowS = piece.RowS;
    const int rowT = piece.RowT;
    const bool south = rowT >= rowS; // u increases (moves south) along the piece
    const int rowNorth = south ? rowS : rowT;
    for (int j = this->RowMin; j < rowNorth; ++j)
    {
      at(j) += piece.Sign * grid.RowHeight[j] * length;
    }

    // The branch of phi - Phi0 in [k pi, (k+1) pi] on which the piece lies.
    const double phi0 = rowS == rowT ? 0.0 : edge.GetPhi0();
    const double k = std::floor((0.5 * (piece.S + piece.T) - phi0) / M_PI);
    const double parity = (static_cast<long>(k) % 2 == 0) ? 1.0 : -1.0;
    auto crossing = [&](int boundaryRow, double& phi, double& anti) {
      // Where the great circle meets u = u_k: q = n_z u_k / sin(theta_k).
      const double q = edge.Normal.z() * grid.RowU[boundaryRow] / grid.RowSine[boundaryRow];
      double cosine = parity * q / edge.Rho;
      if (!(cosine > -1.0))
      {
        cosine = -1.0;
      }
      if (!(cosine < 1.0))
      {
        cosine = 1.0;
      }
      phi = std::clamp(phi0 + k * M_PI + std::acos(cosine), piece.S, piece.T);
      const double p = parity * std::sqrt(std::max(0.0, edge.Rho * edge.Rho - q * q));
      const double r = std::abs(edge.Normal.z()) / grid.RowSine[boundaryRow];
      anti = edge.Sign * std::atan2(p, r);
    };

    double phiPrevious = piece.S, antiPrevious = piece.AntiS;
    if (south)
    {
      for (int j = rowS; j <= rowT; ++j)
      {
        double phiNext = piece.T, antiNext = piece.AntiT;
        if (j < rowT)
        {
          crossing(j + 1, phiNext, antiNext);
        }
        at(j) += piece.Sign * ((antiNext - antiPrevious) - grid.RowU[j] * (phiNext - phiPrevious) +
                                grid.RowHeight[j] * (piece.T - phiNext));
        phiPrevious = phiNext;
        antiPrevious = antiNext;
      }
    }
    else
    {
      for (int j = rowS; j >= rowT; --j)
      {
        double phiNext = piece.T, antiNext = piece.AntiT;
        if (j > rowT)
        {
          crossing(j, phiNext, antiNext);
        }
        at(j) += piece.Sign * (grid.RowHeight[j] * (phiPrevious - piece.S) +
                                (antiNext - antiPrevious) - grid.RowU[j] * (phiNext - phiPrevious));
        phiPrevious = phiNext;
        antiPrevious = antiNext;
      }
    }
  }

  const GridGeometry& Grid;
  Accumulator& Out;
  std::vector<Edge> Edges;
  std::vector<Piece> Pieces;
  std::vector<double> Local;
  std::vector<double> Swept; // net signed azimuth swept per local column
  int RowMin = 0, RowMax = 0;
};

bool Validate(const Points& points, const Triangles& triangles, const Vector& areas, int resolution,
  std::string& error)
{
  std::ostringstream message;
  if (resolution < MinimumGridResolution || resolution % 2 != 0)
  {
    message << "grid resolution must be even and at least " << MinimumGridResolution << " (got "
            << resolution << ")";
    error = message.str();
    return false;
  }
  if (areas.size() != triangles.rows())
  {
    message << "expected one area per triangle: " << triangles.rows() << " triangles but "
            << areas.size() << " areas";
    error = message.str();
    return false;
  }
  for (Eigen::Index k = 0; k < points.rows(); ++k)
  {
    const double norm = points.row(k).norm();
    if (!(std::abs(norm - 1.0) <= 1e-6))
    {
      message << "point " << k << " is not on the unit sphere (|p| = " << norm
              << ", tolerance 1e-6)";
      error = message.str();
      return false;
    }
  }
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    for (int corner = 0; corner < 3; ++corner)
    {
      if (triangles(t, corner) < 0 || triangles(t, corner) >= points.rows())
      {
        message << "triangle " << t << " refers to point " << triangles(t, corner)
                << ", outside [0, " << points.rows() << ")";
        error = message.str();
        return false;
      }
    }
    if (!std::isfinite(areas[t]) || areas[t] < 0.0)
    {
      message << "triangle " << t << " has area " << areas[t]
              << "; areas must be finite and non-negative";
      error = message.str();
      return false;
    }
  }
  error.clear();
  return true;
}
}

double SphericalGridCellArea(int resolution, int row)
{
  return 2.0 * M_PI / resolution * 2.0 * std::sin(M_PI * (row + 0.5) / resolution) *
    std::sin(M_PI / (2.0 * resolution));
}

bool RasterizeSphericalAreas(const Points& spherePoints, const Triangles& triangles,
  const Vector& triangleAreas, int resolution, ScaleFactorValue value,
  SphericalAreaGridResult& result, std::string& error, const ProgressCallback& progress,
  int numberOfThreads)
{
  if (!Validate(spherePoints, triangles, triangleAreas, resolution, error))
  {
    return false;
  }
  const int n = resolution;
  const GridGeometry grid(n);

  std::vector<Vertex> vertices(spherePoints.rows());
  for (Eigen::Index k = 0; k < spherePoints.rows(); ++k)
  {
    Vertex& v = vertices[k];
    v.X = spherePoints.row(k).transpose().normalized();
    v.Phi = std::atan2(v.X.y(), v.X.x());
    if (v.Phi < 0.0)
    {
      v.Phi += 2.0 * M_PI;
    }
    if (v.Phi >= 2.0 * M_PI)
    {
      v.Phi = 0.0;
    }
    v.Row = grid.Row(-v.X.z());
    v.Column = grid.Column(v.Phi);
  }

  // The triangles are split into a fixed number of parts, whatever the thread count, each
  // rasterized into its own accumulator from zero, and the parts are added up in part order:
  // the grid is the same bit for bit on any number of threads. Threads take a wave of parts
  // at a time, so at most one accumulator per thread (and the total) is alive.
  const Eigen::Index triangleCount = triangles.rows();
  const int parts = static_cast<int>(std::min<Eigen::Index>(
    MaximumRasterParts, (triangleCount + TrianglesPerRasterPart - 1) / TrianglesPerRasterPart));
  const int threads = std::max(1, std::min(ResolveThreadCount(numberOfThreads), parts));
  std::vector<Accumulator> accumulators;
  accumulators.reserve(threads);
  for (int t = 0; t < threads; ++t)
  {
    accumulators.emplace_back(n);
  }
  std::unique_ptr<Accumulator> sum; // the parts of earlier waves, when there are several
  std::atomic<bool> aborted(false);
  for (int first = 0; first < std::max(parts, 1) && !aborted; first += threads)
  {
    const int wave = std::max(1, std::min(threads, parts - first));
    // ParallelFor carries an exception (std::bad_alloc) to this thread.
    ParallelFor(wave, wave, [&](int slot, int thread) {
      const int part = first + slot;
      Accumulator& accumulator = accumulators[slot];
      if (first > 0)
      {
        accumulator.Clear();
      }
      TriangleRasterizer rasterizer(grid, accumulator);
      const Eigen::Index begin = parts > 0 ? triangleCount * part / parts : 0;
      const Eigen::Index end = parts > 0 ? triangleCount * (part + 1) / parts : 0;
      for (Eigen::Index t = begin; t < end; ++t)
      {
        if ((t - begin) % 4096 == 0)
        {
          if (aborted)
          {
            return;
          }
          // Only the calling thread reports progress (VTK progress is not thread-safe).
          if (thread == 0 && progress &&
            !progress(0.9 * (part + double(t - begin) / double(end - begin)) / parts))
          {
            aborted = true;
            return;
          }
        }
        rasterizer.Add(vertices[triangles(t, 0)], vertices[triangles(t, 1)],
          vertices[triangles(t, 2)], triangleAreas[t]);
      }
    });
    if (aborted)
    {
      break;
    }
    // Add this wave's parts in part order; 0 + x is exact, so the first part's accumulator
    // can serve as the sum when it is the only wave.
    int slot = 0;
    if (!sum)
    {
      if (parts <= threads)
      {
        for (slot = 1; slot < wave; ++slot)
        {
          accumulators[0].Add(accumulators[slot]);
        }
        break;
      }
      sum.reset(new Accumulator(std::move(accumulators[0])));
      accumulators[0] = Accumulator(n);
      slot = 1;
    }
    for (; slot < wave; ++slot)
    {
      sum->Add(accumulators[slot]);
    }
  }
  if (aborted)
  {
    error = "aborted";
    return false;
  }
  Accumulator& total = sum ? *sum : accumulators[0];

  // Expand the pole markers, divide by the cell areas.
  std::vector<double> north(n, 0.0), south(n, 0.0);
  for (int j = n - 1; j >= 0; --j) // north[i] = sum_{k > j} NorthMarker[k][i]
  {
    for (int i = 0; i < n; ++i)
    {
      north[i] += total.NorthMarker[size_t(j + 1) * n + i];
      total.Cells[size_t(j) * n + i] += grid.RowHeight[j] * north[i];
    }
  }
  for (int j = 0; j < n; ++j) // south[i] = sum_{k < j} SouthMarker[k][i]
  {
    for (int i = 0; i < n; ++i)
    {
      total.Cells[size_t(j) * n + i] += grid.RowHeight[j] * south[i];
      south[i] += total.SouthMarker[size_t(j) * n + i];
    }
  }

  result.Resolution = n;
  result.TotalArea = triangleAreas.sum();
  result.Values.resize(size_t(n) * n);
  for (int j = 0; j < n; ++j)
  {
    const double cellArea = grid.ColumnWidth * grid.RowHeight[j];
    for (int i = 0; i < n; ++i)
    {
      const double ratio = std::max(0.0, total.Cells[size_t(j) * n + i]) / cellArea;
      result.Values[size_t(j) * n + i] =
        value == ScaleFactorValue::SquareRootAreaRatio ? std::sqrt(ratio) : ratio;
    }
  }
  if (progress)
  {
    progress(1.0);
  }
  return true;
}
}
