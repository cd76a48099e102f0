// The kernels' texture lookup from the host, for the texture tests.
#pragma once

#include <cstdint>
#include <vector>

#include "host/scene/scene.hpp"
#include "host/scene/texture.hpp"
#include "tests/cl_test_env.hpp"

namespace facet::test {

// texture_sample on the kernels at each (u, v, lod) of scene texture 0.
inline std::vector<cl_float4> texture_lookup(const TextureImage& t, const std::vector<cl_float4>& uvl) {
    Scene scene;
    scene.textures.push_back(t);
    Material m = default_material();
    m.textures.base_color = 0;
    scene.materials.push_back(m);
    FcTriShading sh{};
    scene.shading.push_back(sh);
    DeviceTextures d = compile_textures(scene);
    ClContext& ctx = context();
    cl::Kernel k(program("kernels/test/texture_kernels.cl"), "texture_lookup_batch");
    cl::Buffer table(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, d.table.size() * sizeof(FcTexture),
                     d.table.data());
    cl::Buffer texels(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, d.texels.size() * sizeof(float),
                      d.texels.data());
    cl::Buffer in(ctx.context(), CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR, uvl.size() * sizeof(cl_float4),
                  const_cast<cl_float4*>(uvl.data()));
    cl::Buffer out(ctx.context(), CL_MEM_WRITE_ONLY, uvl.size() * sizeof(cl_float4));
    k.setArg(0, table);
    k.setArg(1, texels);
    k.setArg(2, 0);
    k.setArg(3, in);
    k.setArg(4, out);
    ctx.queue().enqueueNDRangeKernel(k, cl::NullRange, cl::NDRange(uvl.size()));
    std::vector<cl_float4> result(uvl.size());
    ctx.queue().enqueueReadBuffer(out, CL_TRUE, 0, result.size() * sizeof(cl_float4), result.data());
    return result;
}

}  // namespace facet::test
