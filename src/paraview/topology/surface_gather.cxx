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

}  // namespace flowsurf::paraview
