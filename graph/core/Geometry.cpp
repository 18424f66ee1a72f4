#include "graph/core/Geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace arcomp {

std::vector<glm::vec3> computeVertexNormals(const std::vector<glm::vec3>& positions,
                                            const std::vector<std::uint32_t>& indices) {
    std::vector<glm::vec3> normals(positions.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
        // The cross product's length is twice the area: larger faces weigh more.
        const glm::vec3 n = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
        normals[a] += n;
        normals[b] += n;
        normals[c] += n;
    }
    for (glm::vec3& n : normals) {
        const float len = glm::length(n);
        n = len > 0.0f ? n / len : glm::vec3(0.0f, 0.0f, 1.0f);
    }
    return normals;
}

namespace {

// Any unit vector perpendicular to the unit vector n: the cross product with
// the axis n leans on least is never short.
glm::vec3 anyPerpendicular(const glm::vec3& n) {
    const glm::vec3 a = std::abs(n.x) < 0.57f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(n, a));
}

float cornerAngle(const glm::vec3& from, const glm::vec3& to1, const glm::vec3& to2) {
    const glm::vec3 a = to1 - from, b = to2 - from;
    const float la = glm::length(a), lb = glm::length(b);
    if (la == 0.0f || lb == 0.0f) return 0.0f;
    return std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0f, 1.0f));
}

}  // namespace

std::vector<glm::vec4> computeTangents(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
                                       const std::vector<glm::vec2>& texcoords,
                                       const std::vector<std::uint32_t>& indices) {
    const std::size_t n = positions.size();
    std::vector<glm::vec3> tangentSum(n, glm::vec3(0.0f)), bitangentSum(n, glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t v[3] = {indices[t], indices[t + 1], indices[t + 2]};
        const glm::vec3 e1 = positions[v[1]] - positions[v[0]], e2 = positions[v[2]] - positions[v[0]];
        const glm::vec2 d1 = texcoords[v[1]] - texcoords[v[0]], d2 = texcoords[v[2]] - texcoords[v[0]];
        const float det = d1.x * d2.y - d2.x * d1.y;
        if (!(std::abs(det) > 1e-12f)) continue;  // no UV area: no direction to give
        // dP/du and dP/dv, each normalised: MikkTSpace weighs a triangle's
        // direction by its corner angle, not by its size in uv space.
        const glm::vec3 dPdu = (e1 * d2.y - e2 * d1.y) / det;
        const glm::vec3 dPdv = (e2 * d1.x - e1 * d2.x) / det;
        const float lu = glm::length(dPdu), lv = glm::length(dPdv);
        if (!(lu > 0.0f) || !(lv > 0.0f) || !std::isfinite(lu) || !std::isfinite(lv)) continue;
        // glTF's v grows downwards in the image; the bitangent points up it.
        const glm::vec3 tangent = dPdu / lu, bitangent = -dPdv / lv;
        for (int c = 0; c < 3; ++c) {
            const float w = cornerAngle(positions[v[c]], positions[v[(c + 1) % 3]], positions[v[(c + 2) % 3]]);
            tangentSum[v[c]] += tangent * w;
            bitangentSum[v[c]] += bitangent * w;
        }
    }
    std::vector<glm::vec4> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3& nrm = normals[i];
        glm::vec3 t = tangentSum[i] - nrm * glm::dot(nrm, tangentSum[i]);
        const float len = glm::length(t);
        if (len > 1e-6f && std::isfinite(len)) {
            t /= len;
        } else {
            // No tangent of its own: u along the bitangent's right hand if
            // there is one, else any direction in the surface.
            const glm::vec3 b = bitangentSum[i] - nrm * glm::dot(nrm, bitangentSum[i]);
            const float lb = glm::length(b);
            t = lb > 1e-6f && std::isfinite(lb) ? glm::cross(b / lb, nrm) : anyPerpendicular(nrm);
        }
        const float w = glm::dot(glm::cross(nrm, t), bitangentSum[i]) < 0.0f ? -1.0f : 1.0f;
        out[i] = glm::vec4(t, w);
    }
    return out;
}

void Geometry::finalize() {
    if (normals.size() != positions.size()) normals = computeVertexNormals(positions, indices);
    box = boxAround(positions);
    bound = sphereAround(positions);
}

Geometry makeUvSphere(float radius, int slices, int stacks) {
    Geometry g;
    for (int j = 0; j <= stacks; ++j) {
        const float v = static_cast<float>(j) / static_cast<float>(stacks);
        const float phi = v * std::numbers::pi_v<float>;
        for (int i = 0; i <= slices; ++i) {
            const float u = static_cast<float>(i) / static_cast<float>(slices);
            const float theta = u * 2.0f * std::numbers::pi_v<float>;
            const glm::vec3 n{std::sin(phi) * std::cos(theta), std::cos(phi), std::sin(phi) * std::sin(theta)};
            g.positions.push_back(n * radius);
            g.normals.push_back(n);
            g.texcoords.push_back({u, v});
        }
    }
    const auto at = [slices](int i, int j) { return static_cast<std::uint32_t>(j * (slices + 1) + i); };
    for (int j = 0; j < stacks; ++j) {
        for (int i = 0; i < slices; ++i) {
            // Counter-clockwise seen from outside; the pole rows lose their
            // degenerate half.
            if (j != 0) g.indices.insert(g.indices.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});
            if (j != stacks - 1) g.indices.insert(g.indices.end(), {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    g.finalize();
    return g;
}

Geometry makeBox(const glm::vec3& size) {
    Geometry g;
    const glm::vec3 h = size * 0.5f;
    const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {1.0f, -1.0f}) {
            const glm::vec3 n = axes[axis] * sign;
            const glm::vec3 u = axes[(axis + 1) % 3] * sign;
            const glm::vec3 v = axes[(axis + 2) % 3];
            const auto base = static_cast<std::uint32_t>(g.positions.size());
            for (int k = 0; k < 4; ++k) {
                const float su = (k == 1 || k == 2) ? 1.0f : -1.0f;
                const float sv = (k >= 2) ? 1.0f : -1.0f;
                g.positions.push_back(h * (n + u * su + v * sv));
                g.normals.push_back(n);
                g.texcoords.push_back({(su + 1) * 0.5f, (sv + 1) * 0.5f});
            }
            g.indices.insert(g.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        }
    }
    g.finalize();
    return g;
}

}  // namespace arcomp
