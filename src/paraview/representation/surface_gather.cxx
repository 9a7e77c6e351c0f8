#include "surface_gather.h"

#include "vtkMultiProcessController.h"

#include <numeric>
#include <vector>

namespace flowsurf::paraview {

namespace {

bool parallel(vtkMultiProcessController* c)
{
  return c && c->GetNumberOfProcesses() > 1;
}

// Every process's `count` values on process 0, concatenated in process order (empty elsewhere).
template <typename T>
std::vector<T> gatherValues(vtkMultiProcessController* c, const T* values, vtkIdType count)
{
  const int n = c->GetNumberOfProcesses();
  std::vector<vtkIdType> lengths(size_t(n), 0), offsets(size_t(n), 0);
  c->Gather(&count, lengths.data(), 1, 0);
  std::vector<T> all;
  if (c->GetLocalProcessId() == 0)
  {
    std::partial_sum(lengths.begin(), lengths.end() - 1, offsets.begin() + 1);
    all.resize(size_t(offsets.back() + lengths.back()));
  }
  c->GatherV(values, all.data(), count, lengths.data(), offsets.data(), 0);
  return all;
}

}  // namespace

std::string agreedError(vtkMultiProcessController* c, const std::string& mine)
{
  if (!parallel(c))
  {
    return mine;
  }
  const int n = c->GetNumberOfProcesses();
  int length = int(mine.size());
  std::vector<int> lengths(size_t(n), 0);
  c->AllGather(&length, lengths.data(), 1);
  for (int q = 0; q < n; ++q)
  {
    if (lengths[size_t(q)] == 0)
    {
      continue;
    }
    std::string text = c->GetLocalProcessId() == q ? mine : std::string(size_t(lengths[size_t(q)]), ' ');
    c->Broadcast(text.data(), vtkIdType(text.size()), q);
    return text + " (on process " + std::to_string(q) + " of " + std::to_string(n) + ")";
  }
  return {};
}

core::SurfaceMesh gatherToRoot(vtkMultiProcessController* c, const core::SurfaceMesh& piece)
{
  if (!parallel(c))
  {
    core::SurfaceMesh whole = piece;
    whole.normals.clear();
    return whole;
  }
  const std::vector<glm::vec3> none;
  const std::vector<glm::vec3>& field = piece.fields.empty() ? none : piece.fields[0].values;
  // Positions and field vectors as one float array per vertex (6 floats), triangles as
  // indices into the piece, offset below by the vertices of the processes before.
  std::vector<float> vertices;
  vertices.reserve(piece.positions.size() * 6);
  for (size_t i = 0; i < piece.positions.size(); ++i)
  {
    const glm::vec3 v = i < field.size() ? field[i] : glm::vec3(0.0f);
    vertices.insert(vertices.end(), { piece.positions[i].x, piece.positions[i].y, piece.positions[i].z, v.x, v.y, v.z });
  }
  std::vector<unsigned int> triangles;
  triangles.reserve(piece.triangles.size() * 3);
  for (const glm::uvec3& t : piece.triangles)
  {
    triangles.insert(triangles.end(), { t.x, t.y, t.z });
  }
  const unsigned int vertexCount = unsigned(piece.positions.size()), triangleCount = unsigned(piece.triangles.size());
  const int n = c->GetNumberOfProcesses();
  std::vector<unsigned int> vertexCounts(size_t(n), 0), triangleCounts(size_t(n), 0);
  c->Gather(&vertexCount, vertexCounts.data(), 1, 0);
  c->Gather(&triangleCount, triangleCounts.data(), 1, 0);
  const std::vector<float> allVertices = gatherValues(c, vertices.data(), vtkIdType(vertices.size()));
  const std::vector<unsigned int> allTriangles = gatherValues(c, triangles.data(), vtkIdType(triangles.size()));

  core::SurfaceMesh whole;
  if (c->GetLocalProcessId() != 0)
  {
    return whole;
  }
  whole.fields.push_back({ piece.fields.empty() ? std::string() : piece.fields[0].name, {} });
  for (size_t i = 0; i + 5 < allVertices.size(); i += 6)
  {
    whole.positions.emplace_back(allVertices[i], allVertices[i + 1], allVertices[i + 2]);
    whole.fields[0].values.emplace_back(allVertices[i + 3], allVertices[i + 4], allVertices[i + 5]);
  }
  size_t t = 0;
  unsigned int base = 0;
  for (int q = 0; q < n; ++q)
  {
    for (unsigned int k = 0; k < triangleCounts[size_t(q)]; ++k, t += 3)
    {
      whole.triangles.emplace_back(base + allTriangles[t], base + allTriangles[t + 1], base + allTriangles[t + 2]);
    }
    base += vertexCounts[size_t(q)];
  }
  return whole;
}

namespace
{

// The skeleton as one array of doubles (exact for its floats and for counts below 2^53): the
// summary, the points (position, type, index, eigenvalues, merged), then each line (kind,
// length, point count, then x, y, z, strength per point). Written and read only here.
constexpr size_t kPointValues = 10, kLinePointValues = 4;

std::vector<double> skeletonValues(const skeleton::Skeleton& s)
{
  std::vector<double> v{ double(s.eulerCharacteristic), double(s.indexSum), s.closed ? 1.0 : 0.0, double(s.parts),
    double(s.weldedVertices), double(s.triangles), double(s.zeros), s.scale, s.speed99,
    double(s.criticalPoints.size()), double(s.lines.size()) };
  for (const skeleton::CriticalPoint& p : s.criticalPoints)
  {
    v.insert(v.end(), { p.position.x, p.position.y, p.position.z, double(p.type), double(p.index),
                        p.eigenvalues[0].x, p.eigenvalues[0].y, p.eigenvalues[1].x, p.eigenvalues[1].y,
                        double(p.merged) });
  }
  for (const skeleton::SkeletonLine& l : s.lines)
  {
    v.insert(v.end(), { double(l.kind), l.length, double(l.points.size()) });
    for (size_t i = 0; i < l.points.size(); ++i)
    {
      v.insert(v.end(), { l.points[i].x, l.points[i].y, l.points[i].z, i < l.strength.size() ? l.strength[i] : 0.0f });
    }
  }
  return v;
}

skeleton::Skeleton skeletonFromValues(const std::vector<double>& v)
{
  skeleton::Skeleton s;
  s.eulerCharacteristic = long(v[0]);
  s.indexSum = long(v[1]);
  s.closed = v[2] != 0.0;
  s.parts = size_t(v[3]);
  s.weldedVertices = size_t(v[4]);
  s.triangles = size_t(v[5]);
  s.zeros = size_t(v[6]);
  s.scale = float(v[7]);
  s.speed99 = float(v[8]);
  s.criticalPoints.resize(size_t(v[9]));
  s.lines.resize(size_t(v[10]));
  size_t at = 11;
  for (skeleton::CriticalPoint& p : s.criticalPoints)
  {
    const double* q = &v[at];
    p.position = glm::vec3(q[0], q[1], q[2]);
    p.type = skeleton::PointType(int(q[3]));
    p.index = int(q[4]);
    p.eigenvalues[0] = glm::vec2(q[5], q[6]);
    p.eigenvalues[1] = glm::vec2(q[7], q[8]);
    p.merged = size_t(q[9]);
    at += kPointValues;
  }
  for (skeleton::SkeletonLine& l : s.lines)
  {
    l.kind = skeleton::LineKind(int(v[at]));
    l.length = float(v[at + 1]);
    const size_t n = size_t(v[at + 2]);
    at += 3;
    for (size_t i = 0; i < n; ++i, at += kLinePointValues)
    {
      l.points.emplace_back(v[at], v[at + 1], v[at + 2]);
      l.strength.push_back(float(v[at + 3]));
    }
  }
  return s;
}

}  // namespace

skeleton::Skeleton broadcastFromRoot(vtkMultiProcessController* c, const skeleton::Skeleton& result)
{
  if (!parallel(c))
  {
    return result;
  }
  std::vector<double> values;
  if (c->GetLocalProcessId() == 0)
  {
    values = skeletonValues(result);
  }
  vtkIdType length = vtkIdType(values.size());
  c->Broadcast(&length, 1, 0);
  values.resize(size_t(length));
  c->Broadcast(values.data(), length, 0);
  return skeletonFromValues(values);
}

}  // namespace flowsurf::paraview
