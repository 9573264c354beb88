// SPDX-License-Identifier: MIT
// Copyright 2026 the MeshFair authors.
#pragma once

// The OpenGL 3.3 core functions MeshFair calls, as a table of pointers filled from the
// current context's GetProcAddress (GLFW's or OSMesa's). Neither libepoxy, GLEW nor
// ImGui's own loader works under OSMesa, and calling the gl* symbols directly with both
// libGL (through GLFW) and libOSMesa in one process binds whichever the link order
// picks. Including this header makes every glXxx name a call through the table; it is
// included by render/gl_* files only (and by the ImGui backend's wrapper).

#include <GL/glcorearb.h>

#include "app/render/gl_loader.h"

namespace meshfair::gl {

// X(pointer type, name without the gl prefix), for every function in the table.
#define MESHFAIR_GL_FUNCTIONS(X)                                   \
    X(PFNGLGETSTRINGPROC, GetString)                               \
    X(PFNGLGETSTRINGIPROC, GetStringi)                             \
    X(PFNGLGETINTEGERVPROC, GetIntegerv)                           \
    X(PFNGLGETERRORPROC, GetError)                                 \
    X(PFNGLVIEWPORTPROC, Viewport)                                 \
    X(PFNGLCLEARCOLORPROC, ClearColor)                             \
    X(PFNGLCLEARPROC, Clear)                                       \
    X(PFNGLCLEARDEPTHPROC, ClearDepth)                             \
    X(PFNGLENABLEPROC, Enable)                                     \
    X(PFNGLDISABLEPROC, Disable)                                   \
    X(PFNGLISENABLEDPROC, IsEnabled)                               \
    X(PFNGLDEPTHFUNCPROC, DepthFunc)                               \
    X(PFNGLDEPTHMASKPROC, DepthMask)                               \
    X(PFNGLPOLYGONOFFSETPROC, PolygonOffset)                       \
    X(PFNGLPOLYGONMODEPROC, PolygonMode)                           \
    X(PFNGLBLENDFUNCPROC, BlendFunc)                               \
    X(PFNGLBLENDFUNCSEPARATEPROC, BlendFuncSeparate)               \
    X(PFNGLBLENDEQUATIONPROC, BlendEquation)                       \
    X(PFNGLBLENDEQUATIONSEPARATEPROC, BlendEquationSeparate)       \
    X(PFNGLSCISSORPROC, Scissor)                                   \
    X(PFNGLREADPIXELSPROC, ReadPixels)                             \
    X(PFNGLPIXELSTOREIPROC, PixelStorei)                           \
    X(PFNGLDRAWELEMENTSPROC, DrawElements)                         \
    X(PFNGLDRAWELEMENTSBASEVERTEXPROC, DrawElementsBaseVertex)     \
    X(PFNGLDRAWARRAYSPROC, DrawArrays)                             \
    X(PFNGLGENBUFFERSPROC, GenBuffers)                             \
    X(PFNGLDELETEBUFFERSPROC, DeleteBuffers)                       \
    X(PFNGLBINDBUFFERPROC, BindBuffer)                             \
    X(PFNGLBUFFERDATAPROC, BufferData)                             \
    X(PFNGLBUFFERSUBDATAPROC, BufferSubData)                       \
    X(PFNGLGENVERTEXARRAYSPROC, GenVertexArrays)                   \
    X(PFNGLDELETEVERTEXARRAYSPROC, DeleteVertexArrays)             \
    X(PFNGLBINDVERTEXARRAYPROC, BindVertexArray)                   \
    X(PFNGLENABLEVERTEXATTRIBARRAYPROC, EnableVertexAttribArray)   \
    X(PFNGLDISABLEVERTEXATTRIBARRAYPROC, DisableVertexAttribArray) \
    X(PFNGLVERTEXATTRIBPOINTERPROC, VertexAttribPointer)           \
    X(PFNGLVERTEXATTRIBIPOINTERPROC, VertexAttribIPointer)         \
    X(PFNGLVERTEXATTRIB3FPROC, VertexAttrib3f)                     \
    X(PFNGLCREATESHADERPROC, CreateShader)                         \
    X(PFNGLSHADERSOURCEPROC, ShaderSource)                         \
    X(PFNGLCOMPILESHADERPROC, CompileShader)                       \
    X(PFNGLGETSHADERIVPROC, GetShaderiv)                           \
    X(PFNGLGETSHADERINFOLOGPROC, GetShaderInfoLog)                 \
    X(PFNGLDELETESHADERPROC, DeleteShader)                         \
    X(PFNGLCREATEPROGRAMPROC, CreateProgram)                       \
    X(PFNGLATTACHSHADERPROC, AttachShader)                         \
    X(PFNGLDETACHSHADERPROC, DetachShader)                         \
    X(PFNGLLINKPROGRAMPROC, LinkProgram)                           \
    X(PFNGLGETPROGRAMIVPROC, GetProgramiv)                         \
    X(PFNGLGETPROGRAMINFOLOGPROC, GetProgramInfoLog)               \
    X(PFNGLDELETEPROGRAMPROC, DeleteProgram)                       \
    X(PFNGLUSEPROGRAMPROC, UseProgram)                             \
    X(PFNGLISPROGRAMPROC, IsProgram)                               \
    X(PFNGLGETUNIFORMLOCATIONPROC, GetUniformLocation)             \
    X(PFNGLGETATTRIBLOCATIONPROC, GetAttribLocation)               \
    X(PFNGLUNIFORM1IPROC, Uniform1i)                               \
    X(PFNGLUNIFORM1FPROC, Uniform1f)                               \
    X(PFNGLUNIFORM2FPROC, Uniform2f)                               \
    X(PFNGLUNIFORM3FPROC, Uniform3f)                               \
    X(PFNGLUNIFORM4FPROC, Uniform4f)                               \
    X(PFNGLUNIFORMMATRIX3FVPROC, UniformMatrix3fv)                 \
    X(PFNGLUNIFORMMATRIX4FVPROC, UniformMatrix4fv)                 \
    X(PFNGLGENTEXTURESPROC, GenTextures)                           \
    X(PFNGLDELETETEXTURESPROC, DeleteTextures)                     \
    X(PFNGLBINDTEXTUREPROC, BindTexture)                           \
    X(PFNGLACTIVETEXTUREPROC, ActiveTexture)                       \
    X(PFNGLTEXBUFFERPROC, TexBuffer)                               \
    X(PFNGLTEXIMAGE2DPROC, TexImage2D)                             \
    X(PFNGLTEXPARAMETERIPROC, TexParameteri)                       \
    X(PFNGLBINDSAMPLERPROC, BindSampler)                           \
    X(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers)                   \
    X(PFNGLDELETEFRAMEBUFFERSPROC, DeleteFramebuffers)             \
    X(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer)                   \
    X(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D)         \
    X(PFNGLFRAMEBUFFERRENDERBUFFERPROC, FramebufferRenderbuffer)   \
    X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, CheckFramebufferStatus)     \
    X(PFNGLBLITFRAMEBUFFERPROC, BlitFramebuffer)                   \
    X(PFNGLGENRENDERBUFFERSPROC, GenRenderbuffers)                 \
    X(PFNGLDELETERENDERBUFFERSPROC, DeleteRenderbuffers)           \
    X(PFNGLBINDRENDERBUFFERPROC, BindRenderbuffer)                 \
    X(PFNGLRENDERBUFFERSTORAGEPROC, RenderbufferStorage)           \
    X(PFNGLDRAWBUFFERSPROC, DrawBuffers)                           \
    X(PFNGLREADBUFFERPROC, ReadBuffer)                             \
    X(PFNGLCLEARBUFFERUIVPROC, ClearBufferuiv)                     \
    X(PFNGLCLEARBUFFERFVPROC, ClearBufferfv)                       \
    X(PFNGLFINISHPROC, Finish)                                     \
    X(PFNGLFLUSHPROC, Flush)

struct Functions
{
#define MESHFAIR_GL_MEMBER(type, name) type name = nullptr;
    MESHFAIR_GL_FUNCTIONS(MESHFAIR_GL_MEMBER)
#undef MESHFAIR_GL_MEMBER
};

//! The table the glXxx names call through; filled by load_functions.
extern Functions g_functions;

} // namespace meshfair::gl

#define MESHFAIR_GL_CALL(name) ::meshfair::gl::g_functions.name
#define glGetString MESHFAIR_GL_CALL(GetString)
#define glGetStringi MESHFAIR_GL_CALL(GetStringi)
#define glGetIntegerv MESHFAIR_GL_CALL(GetIntegerv)
#define glGetError MESHFAIR_GL_CALL(GetError)
#define glViewport MESHFAIR_GL_CALL(Viewport)
#define glClearColor MESHFAIR_GL_CALL(ClearColor)
#define glClear MESHFAIR_GL_CALL(Clear)
#define glClearDepth MESHFAIR_GL_CALL(ClearDepth)
#define glEnable MESHFAIR_GL_CALL(Enable)
#define glDisable MESHFAIR_GL_CALL(Disable)
#define glIsEnabled MESHFAIR_GL_CALL(IsEnabled)
#define glDepthFunc MESHFAIR_GL_CALL(DepthFunc)
#define glDepthMask MESHFAIR_GL_CALL(DepthMask)
#define glPolygonOffset MESHFAIR_GL_CALL(PolygonOffset)
#define glPolygonMode MESHFAIR_GL_CALL(PolygonMode)
#define glBlendFunc MESHFAIR_GL_CALL(BlendFunc)
#define glBlendFuncSeparate MESHFAIR_GL_CALL(BlendFuncSeparate)
#define glBlendEquation MESHFAIR_GL_CALL(BlendEquation)
#define glBlendEquationSeparate MESHFAIR_GL_CALL(BlendEquationSeparate)
#define glScissor MESHFAIR_GL_CALL(Scissor)
#define glReadPixels MESHFAIR_GL_CALL(ReadPixels)
#define glPixelStorei MESHFAIR_GL_CALL(PixelStorei)
#define glDrawElements MESHFAIR_GL_CALL(DrawElements)
#define glDrawElementsBaseVertex MESHFAIR_GL_CALL(DrawElementsBaseVertex)
#define glDrawArrays MESHFAIR_GL_CALL(DrawArrays)
#define glGenBuffers MESHFAIR_GL_CALL(GenBuffers)
#define glDeleteBuffers MESHFAIR_GL_CALL(DeleteBuffers)
#define glBindBuffer MESHFAIR_GL_CALL(BindBuffer)
#define glBufferData MESHFAIR_GL_CALL(BufferData)
#define glBufferSubData MESHFAIR_GL_CALL(BufferSubData)
#define glGenVertexArrays MESHFAIR_GL_CALL(GenVertexArrays)
#define glDeleteVertexArrays MESHFAIR_GL_CALL(DeleteVertexArrays)
#define glBindVertexArray MESHFAIR_GL_CALL(BindVertexArray)
#define glEnableVertexAttribArray MESHFAIR_GL_CALL(EnableVertexAttribArray)
#define glDisableVertexAttribArray MESHFAIR_GL_CALL(DisableVertexAttribArray)
#define glVertexAttribPointer MESHFAIR_GL_CALL(VertexAttribPointer)
#define glVertexAttribIPointer MESHFAIR_GL_CALL(VertexAttribIPointer)
#define glVertexAttrib3f MESHFAIR_GL_CALL(VertexAttrib3f)
#define glCreateShader MESHFAIR_GL_CALL(CreateShader)
#define glShaderSource MESHFAIR_GL_CALL(ShaderSource)
#define glCompileShader MESHFAIR_GL_CALL(CompileShader)
#define glGetShaderiv MESHFAIR_GL_CALL(GetShaderiv)
#define glGetShaderInfoLog MESHFAIR_GL_CALL(GetShaderInfoLog)
#define glDeleteShader MESHFAIR_GL_CALL(DeleteShader)
#define glCreateProgram MESHFAIR_GL_CALL(CreateProgram)
#define glAttachShader MESHFAIR_GL_CALL(AttachShader)
#define glDetachShader MESHFAIR_GL_CALL(DetachShader)
#define glLinkProgram MESHFAIR_GL_CALL(LinkProgram)
#define glGetProgramiv MESHFAIR_GL_CALL(GetProgramiv)
#define glGetProgramInfoLog MESHFAIR_GL_CALL(GetProgramInfoLog)
#define glDeleteProgram MESHFAIR_GL_CALL(DeleteProgram)
#define glUseProgram MESHFAIR_GL_CALL(UseProgram)
#define glIsProgram MESHFAIR_GL_CALL(IsProgram)
#define glGetUniformLocation MESHFAIR_GL_CALL(GetUniformLocation)
#define glGetAttribLocation MESHFAIR_GL_CALL(GetAttribLocation)
#define glUniform1i MESHFAIR_GL_CALL(Uniform1i)
#define glUniform1f MESHFAIR_GL_CALL(Uniform1f)
#define glUniform2f MESHFAIR_GL_CALL(Uniform2f)
#define glUniform3f MESHFAIR_GL_CALL(Uniform3f)
#define glUniform4f MESHFAIR_GL_CALL(Uniform4f)
#define glUniformMatrix3fv MESHFAIR_GL_CALL(UniformMatrix3fv)
#define glUniformMatrix4fv MESHFAIR_GL_CALL(UniformMatrix4fv)
#define glGenTextures MESHFAIR_GL_CALL(GenTextures)
#define glDeleteTextures MESHFAIR_GL_CALL(DeleteTextures)
#define glBindTexture MESHFAIR_GL_CALL(BindTexture)
#define glActiveTexture MESHFAIR_GL_CALL(ActiveTexture)
#define glTexBuffer MESHFAIR_GL_CALL(TexBuffer)
#define glTexImage2D MESHFAIR_GL_CALL(TexImage2D)
#define glTexParameteri MESHFAIR_GL_CALL(TexParameteri)
#define glBindSampler MESHFAIR_GL_CALL(BindSampler)
#define glGenFramebuffers MESHFAIR_GL_CALL(GenFramebuffers)
#define glDeleteFramebuffers MESHFAIR_GL_CALL(DeleteFramebuffers)
#define glBindFramebuffer MESHFAIR_GL_CALL(BindFramebuffer)
#define glFramebufferTexture2D MESHFAIR_GL_CALL(FramebufferTexture2D)
#define glFramebufferRenderbuffer MESHFAIR_GL_CALL(FramebufferRenderbuffer)
#define glCheckFramebufferStatus MESHFAIR_GL_CALL(CheckFramebufferStatus)
#define glBlitFramebuffer MESHFAIR_GL_CALL(BlitFramebuffer)
#define glGenRenderbuffers MESHFAIR_GL_CALL(GenRenderbuffers)
#define glDeleteRenderbuffers MESHFAIR_GL_CALL(DeleteRenderbuffers)
#define glBindRenderbuffer MESHFAIR_GL_CALL(BindRenderbuffer)
#define glRenderbufferStorage MESHFAIR_GL_CALL(RenderbufferStorage)
#define glDrawBuffers MESHFAIR_GL_CALL(DrawBuffers)
#define glReadBuffer MESHFAIR_GL_CALL(ReadBuffer)
#define glClearBufferuiv MESHFAIR_GL_CALL(ClearBufferuiv)
#define glClearBufferfv MESHFAIR_GL_CALL(ClearBufferfv)
#define glFinish MESHFAIR_GL_CALL(Finish)
#define glFlush MESHFAIR_GL_CALL(Flush)
