#include "run/vulkan_compute.h"

#define VK_NO_PROTOTYPES
#include <vulkan/vulkan.h>

#include <dlfcn.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace offsetgen::vulkan {
namespace {

// The Vulkan loader is opened when a run first needs it (dlopen), not linked: the commands that
// never run HLSL do not load it at start. It exports every core function, so each is one dlsym.
#define OFFSETGEN_VULKAN_FUNCTIONS(X)         \
  X(vkAllocateCommandBuffers)                 \
  X(vkAllocateDescriptorSets)                 \
  X(vkAllocateMemory)                         \
  X(vkBeginCommandBuffer)                     \
  X(vkBindBufferMemory)                       \
  X(vkCmdBindDescriptorSets)                  \
  X(vkCmdBindPipeline)                        \
  X(vkCmdDispatch)                            \
  X(vkCmdPipelineBarrier)                     \
  X(vkCreateBuffer)                           \
  X(vkCreateCommandPool)                      \
  X(vkCreateComputePipelines)                 \
  X(vkCreateDescriptorPool)                   \
  X(vkCreateDescriptorSetLayout)              \
  X(vkCreateDevice)                           \
  X(vkCreateFence)                            \
  X(vkCreateInstance)                         \
  X(vkCreatePipelineLayout)                   \
  X(vkCreateShaderModule)                     \
  X(vkDestroyBuffer)                          \
  X(vkDestroyCommandPool)                     \
  X(vkDestroyDescriptorPool)                  \
  X(vkDestroyDescriptorSetLayout)             \
  X(vkDestroyDevice)                          \
  X(vkDestroyFence)                           \
  X(vkDestroyInstance)                        \
  X(vkDestroyPipeline)                        \
  X(vkDestroyPipelineLayout)                  \
  X(vkDestroyShaderModule)                    \
  X(vkEndCommandBuffer)                       \
  X(vkEnumeratePhysicalDevices)               \
  X(vkFreeMemory)                             \
  X(vkGetBufferMemoryRequirements)            \
  X(vkGetDeviceQueue)                         \
  X(vkGetPhysicalDeviceMemoryProperties)      \
  X(vkGetPhysicalDeviceProperties)            \
  X(vkGetPhysicalDeviceQueueFamilyProperties) \
  X(vkMapMemory)                              \
  X(vkQueueSubmit)                            \
  X(vkUnmapMemory)                            \
  X(vkUpdateDescriptorSets)                   \
  X(vkWaitForFences)

#define OFFSETGEN_VULKAN_DECLARE(name) PFN_##name name = nullptr;
OFFSETGEN_VULKAN_FUNCTIONS(OFFSETGEN_VULKAN_DECLARE)
#undef OFFSETGEN_VULKAN_DECLARE

// Fills the pointers above, once per process; throws std::runtime_error when the loader or one of
// the functions is missing.
void load_vulkan() {
  static const std::string failure = [] {
    void* library = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);  // kept open until exit
    if (library == nullptr) return std::string("cannot open libvulkan.so.1 (") + dlerror() + ")";
    std::string missing;
#define OFFSETGEN_VULKAN_LOAD(name)                           \
  name = reinterpret_cast<PFN_##name>(dlsym(library, #name)); \
  if (name == nullptr) missing += " " #name;
    OFFSETGEN_VULKAN_FUNCTIONS(OFFSETGEN_VULKAN_LOAD)
#undef OFFSETGEN_VULKAN_LOAD
    return missing.empty() ? std::string() : "libvulkan.so.1 lacks" + missing;
  }();
  if (!failure.empty())
    throw std::runtime_error(failure + ": install Debian's libvulkan1 and mesa-vulkan-drivers (tools/install_deps.sh)");
}

constexpr std::uint32_t kGroupSize = 64;  // the shader's [numthreads(64, 1, 1)]

void check(VkResult result, const char* call) {
  if (result != VK_SUCCESS) throw std::runtime_error(std::string(call) + " failed: VkResult " + std::to_string(result));
}

// Every object of one run, destroyed in reverse order of creation whatever happens.
struct Context {
  VkInstance instance = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkBuffer buffers[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
  VkDeviceMemory memory[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
  VkShaderModule module = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkDescriptorPool pool = VK_NULL_HANDLE;
  VkCommandPool command_pool = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  ~Context() {
    if (device) {
      vkDestroyFence(device, fence, nullptr);
      vkDestroyCommandPool(device, command_pool, nullptr);
      vkDestroyDescriptorPool(device, pool, nullptr);
      vkDestroyPipeline(device, pipeline, nullptr);
      vkDestroyPipelineLayout(device, pipeline_layout, nullptr);
      vkDestroyDescriptorSetLayout(device, set_layout, nullptr);
      vkDestroyShaderModule(device, module, nullptr);
      for (int i = 0; i < 2; ++i) {
        vkDestroyBuffer(device, buffers[i], nullptr);
        vkFreeMemory(device, memory[i], nullptr);
      }
      vkDestroyDevice(device, nullptr);
    }
    if (instance) vkDestroyInstance(instance, nullptr);
  }
};

// The lavapipe device (VK_PHYSICAL_DEVICE_TYPE_CPU): the tests need no GPU, and give the same
// numbers on every machine.
VkPhysicalDevice cpu_device(VkInstance instance, std::string& name) {
  std::uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  check(vkEnumeratePhysicalDevices(instance, &count, devices.data()), "vkEnumeratePhysicalDevices");
  for (VkPhysicalDevice d : devices) {
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(d, &properties);
    if (properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) {
      name = properties.deviceName;
      return d;
    }
  }
  throw std::runtime_error("no Vulkan CPU device (lavapipe) among " + std::to_string(count) +
                           " devices: install Debian's mesa-vulkan-drivers (tools/install_deps.sh)");
}

std::uint32_t compute_queue_family(VkPhysicalDevice device) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  for (std::uint32_t i = 0; i < count; ++i)
    if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) return i;
  throw std::runtime_error("the Vulkan device has no compute queue");
}

void make_buffer(Context& c, VkPhysicalDevice physical, int index, VkDeviceSize size) {
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = size;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  check(vkCreateBuffer(c.device, &info, nullptr, &c.buffers[index]), "vkCreateBuffer");
  VkMemoryRequirements needs;
  vkGetBufferMemoryRequirements(c.device, c.buffers[index], &needs);
  VkPhysicalDeviceMemoryProperties memory;
  vkGetPhysicalDeviceMemoryProperties(physical, &memory);
  const VkMemoryPropertyFlags wanted = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  std::uint32_t type = memory.memoryTypeCount;
  for (std::uint32_t i = 0; i < memory.memoryTypeCount && type == memory.memoryTypeCount; ++i)
    if ((needs.memoryTypeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & wanted) == wanted) type = i;
  if (type == memory.memoryTypeCount) throw std::runtime_error("no host-visible coherent Vulkan memory");
  VkMemoryAllocateInfo allocate{};
  allocate.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  allocate.allocationSize = needs.size;
  allocate.memoryTypeIndex = type;
  check(vkAllocateMemory(c.device, &allocate, nullptr, &c.memory[index]), "vkAllocateMemory");
  check(vkBindBufferMemory(c.device, c.buffers[index], c.memory[index], 0), "vkBindBufferMemory");
}

}  // namespace

std::vector<std::uint32_t> read_spirv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in && !in.eof()) throw std::runtime_error("cannot read " + path);
  if (bytes.empty() || bytes.size() % 4 != 0) throw std::runtime_error(path + " is not a SPIR-V module");
  std::vector<std::uint32_t> words(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), bytes.size());
  return words;
}

ComputeRun run_on_lavapipe(const std::vector<std::uint32_t>& spirv, const std::vector<Float4>& inputs,
                           int outputs_per_point) {
  load_vulkan();
  Context c;
  ComputeRun run;
  const std::uint32_t groups = static_cast<std::uint32_t>((inputs.size() + kGroupSize - 1) / kGroupSize);
  const std::size_t padded = std::size_t{groups} * kGroupSize;  // every invocation reads and writes its own slot

  VkApplicationInfo app{};

  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "offsetgen hlsl tests";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo instance_info{};
  instance_info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  instance_info.pApplicationInfo = &app;
  check(vkCreateInstance(&instance_info, nullptr, &c.instance), "vkCreateInstance");
  const VkPhysicalDevice physical = cpu_device(c.instance, run.device);
  const std::uint32_t family = compute_queue_family(physical);

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{};
  queue_info.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  queue_info.queueFamilyIndex = family;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;
  VkDeviceCreateInfo device_info{};
  device_info.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  device_info.queueCreateInfoCount = 1;
  device_info.pQueueCreateInfos = &queue_info;
  check(vkCreateDevice(physical, &device_info, nullptr, &c.device), "vkCreateDevice");
  VkQueue queue;
  vkGetDeviceQueue(c.device, family, 0, &queue);

  const VkDeviceSize in_size = padded * sizeof(Float4);
  const VkDeviceSize out_size = padded * sizeof(Float4) * static_cast<std::size_t>(outputs_per_point);
  make_buffer(c, physical, 0, in_size);
  make_buffer(c, physical, 1, out_size);
  void* mapped = nullptr;
  check(vkMapMemory(c.device, c.memory[0], 0, in_size, 0, &mapped), "vkMapMemory");
  std::memset(mapped, 0, in_size);
  if (!inputs.empty()) std::memcpy(mapped, inputs.data(), inputs.size() * sizeof(Float4));
  vkUnmapMemory(c.device, c.memory[0]);

  VkShaderModuleCreateInfo module_info{};

  module_info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  module_info.codeSize = spirv.size() * sizeof(std::uint32_t);
  module_info.pCode = spirv.data();
  check(vkCreateShaderModule(c.device, &module_info, nullptr, &c.module), "vkCreateShaderModule");

  VkDescriptorSetLayoutBinding bindings[2] = {};
  for (std::uint32_t i = 0; i < 2; ++i) {
    bindings[i].binding = i;
    bindings[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    bindings[i].descriptorCount = 1;
    bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  }
  VkDescriptorSetLayoutCreateInfo set_layout_info{};
  set_layout_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  set_layout_info.bindingCount = 2;
  set_layout_info.pBindings = bindings;
  check(vkCreateDescriptorSetLayout(c.device, &set_layout_info, nullptr, &c.set_layout), "vkCreateDescriptorSetLayout");
  VkPipelineLayoutCreateInfo pipeline_layout_info{};
  pipeline_layout_info.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  pipeline_layout_info.setLayoutCount = 1;
  pipeline_layout_info.pSetLayouts = &c.set_layout;
  check(vkCreatePipelineLayout(c.device, &pipeline_layout_info, nullptr, &c.pipeline_layout), "vkCreatePipelineLayout");
  VkComputePipelineCreateInfo pipeline_info{};
  pipeline_info.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
  pipeline_info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  pipeline_info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  pipeline_info.stage.module = c.module;
  pipeline_info.stage.pName = "main";
  pipeline_info.layout = c.pipeline_layout;
  check(vkCreateComputePipelines(c.device, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, &c.pipeline),
        "vkCreateComputePipelines");

  VkDescriptorPoolSize pool_size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 2};
  VkDescriptorPoolCreateInfo pool_info{};
  pool_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  pool_info.maxSets = 1;
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &pool_size;
  check(vkCreateDescriptorPool(c.device, &pool_info, nullptr, &c.pool), "vkCreateDescriptorPool");
  VkDescriptorSetAllocateInfo set_info{};
  set_info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  set_info.descriptorPool = c.pool;
  set_info.descriptorSetCount = 1;
  set_info.pSetLayouts = &c.set_layout;
  VkDescriptorSet set;
  check(vkAllocateDescriptorSets(c.device, &set_info, &set), "vkAllocateDescriptorSets");
  VkDescriptorBufferInfo buffer_infos[2] = {{c.buffers[0], 0, VK_WHOLE_SIZE}, {c.buffers[1], 0, VK_WHOLE_SIZE}};
  VkWriteDescriptorSet writes[2] = {};
  for (std::uint32_t i = 0; i < 2; ++i) {
    writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    writes[i].dstSet = set;
    writes[i].dstBinding = i;
    writes[i].descriptorCount = 1;
    writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[i].pBufferInfo = &buffer_infos[i];
  }
  vkUpdateDescriptorSets(c.device, 2, writes, 0, nullptr);

  VkCommandPoolCreateInfo command_pool_info{};

  command_pool_info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  command_pool_info.queueFamilyIndex = family;
  check(vkCreateCommandPool(c.device, &command_pool_info, nullptr, &c.command_pool), "vkCreateCommandPool");
  VkCommandBufferAllocateInfo command_info{};
  command_info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  command_info.commandPool = c.command_pool;
  command_info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  command_info.commandBufferCount = 1;
  VkCommandBuffer commands;
  check(vkAllocateCommandBuffers(c.device, &command_info, &commands), "vkAllocateCommandBuffers");
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(commands, &begin), "vkBeginCommandBuffer");
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, c.pipeline);
  vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, c.pipeline_layout, 0, 1, &set, 0, nullptr);
  vkCmdDispatch(commands, groups, 1, 1);
  VkMemoryBarrier barrier{};  // the shader's writes, visible to the host
  barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0,
                       nullptr, 0, nullptr);
  check(vkEndCommandBuffer(commands), "vkEndCommandBuffer");

  VkFenceCreateInfo fence_info{};

  fence_info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  check(vkCreateFence(c.device, &fence_info, nullptr, &c.fence), "vkCreateFence");
  VkSubmitInfo submit{};
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands;
  check(vkQueueSubmit(queue, 1, &submit, c.fence), "vkQueueSubmit");
  check(vkWaitForFences(c.device, 1, &c.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");

  const std::size_t floats = inputs.size() * 4 * static_cast<std::size_t>(outputs_per_point);
  run.outputs.resize(floats);
  check(vkMapMemory(c.device, c.memory[1], 0, out_size, 0, &mapped), "vkMapMemory");
  std::memcpy(run.outputs.data(), mapped, floats * sizeof(float));
  vkUnmapMemory(c.device, c.memory[1]);
  return run;
}

}  // namespace offsetgen::vulkan
